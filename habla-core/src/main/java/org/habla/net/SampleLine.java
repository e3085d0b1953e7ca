package org.habla.net;

import com.fasterxml.jackson.core.JsonGenerator;
import com.fasterxml.jackson.core.util.ByteArrayBuilder;
import java.io.IOException;
import java.io.UncheckedIOException;
import org.habla.sample.AudioChunk;
import org.habla.sample.ImageFrame;
import org.habla.sample.NumberValue;
import org.habla.sample.Payload;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordJson;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.habla.sample.TextValue;
import org.habla.sample.VectorValue;

/**
 * A sample's line as a control socket sends it, written straight from the payload with a JSON generator: the
 * fields {@link SampleCodec} documents, in its order, without making the JSON tree that
 * {@link SampleCodec#sampleFrame} makes; a typed record is written field by field from its layout
 * ({@link org.habla.sample.RecordLayout#write}).
 * Every sample of every exposed output is written this way, once for all of the socket's clients.
 */
final class SampleLine {

    private SampleLine() {
    }

    /**
     * The sample line of one output's sample as the bytes a socket gets, newline included: the same bytes as
     * {@link SampleCodec#sampleFrame} encoded. Null for a payload with a body (audio, an image), whose frame is
     * encoded instead.
     */
    static byte[] of(String output, Sample sample) {
        Payload payload = sample.payload();
        if (payload instanceof AudioChunk || payload instanceof ImageFrame) {
            return null;
        }
        try (ByteArrayBuilder bytes = new ByteArrayBuilder(256);
                JsonGenerator g = FrameReader.JSON.createGenerator(bytes)) {
            g.writeStartObject();
            g.writeStringField("type", "sample");
            g.writeStringField("output", output);
            g.writeNumberField("seq", sample.sequence());
            g.writeNumberField("t", sample.sourceMicros());
            g.writeBooleanField("stale", sample.stale());
            g.writeStringField("kind", payload.kind().wireName());
            g.writeFieldName("value");
            switch (payload) {
                case NumberValue n -> RecordJson.writeNumber(n.value(), g);
                case VectorValue v -> {
                    g.writeStartArray();
                    for (int i = 0; i < v.size(); i++) {
                        RecordJson.writeNumber(v.get(i), g);
                    }
                    g.writeEndArray();
                }
                case TextValue t -> g.writeString(t.text());
                case RecordValue r -> writeRecord(r, g);
                default -> throw new IllegalStateException("a " + payload.kind() + " has a body");
            }
            g.writeEndObject();
            g.flush();
            bytes.write('\n');
            return bytes.toByteArray();
        } catch (IOException e) {
            throw new UncheckedIOException("cannot encode a sample of " + output, e);
        }
    }

    private static void writeRecord(RecordValue r, JsonGenerator g) throws IOException {
        RecordForm form = r.carriesForm();
        if (form != null && form.layout().write(form, g)) {
            return;
        }
        g.writeTree(RecordJson.allFinite(r.jsonView()) ? r.jsonView() : SampleCodec.finite(r.json()));
    }
}
