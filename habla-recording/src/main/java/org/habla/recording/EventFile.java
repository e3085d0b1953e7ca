package org.habla.recording;

import java.io.IOException;
import java.io.OutputStream;
import java.nio.file.Path;
import java.util.Locale;
import org.habla.net.FrameWriter;

/**
 * Where the recorder's writer thread puts events: a file in one of the two formats, chosen by the file's name.
 * {@code .mcap} is MCAP ({@link McapEventFile}); any other name is HABLA's own line format
 * ({@link RecordingCodec}).
 */
interface EventFile {

    void write(RecordedEvent e) throws IOException;

    /** Hands what was written to the operating system (a kill loses at most what came after). */
    void flush() throws IOException;

    /** Ends the file cleanly (after the end event): MCAP writes its summary and footer. */
    void finish() throws IOException;

    /** Whether a file of this name is an MCAP recording. */
    static boolean isMcap(Path file) {
        return file.getFileName().toString().toLowerCase(Locale.ROOT).endsWith(".mcap");
    }

    /** The file for {@code name}, its header already written to {@code stream}. */
    static EventFile create(Path name, OutputStream stream, RecordingHeader header) throws IOException {
        if (isMcap(name)) {
            return new McapEventFile(stream, header);
        }
        FrameWriter out = new FrameWriter(stream);
        out.send(RecordingCodec.header(header));
        return new EventFile() {
            @Override
            public void write(RecordedEvent e) throws IOException {
                out.write(RecordingCodec.frame(e));
            }

            @Override
            public void flush() throws IOException {
                out.flush();
            }

            @Override
            public void finish() throws IOException {
                out.flush();
            }
        };
    }
}
