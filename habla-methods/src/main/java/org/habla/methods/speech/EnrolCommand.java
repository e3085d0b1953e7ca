package org.habla.methods.speech;

import java.io.File;
import java.io.IOException;
import java.io.InputStream;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.List;
import java.util.concurrent.Callable;
import javax.sound.sampled.AudioInputStream;
import javax.sound.sampled.AudioSystem;
import javax.sound.sampled.UnsupportedAudioFileException;
import org.habla.command.CommandExtension;
import org.habla.command.ExitCodes;
import org.habla.sample.AudioChunk;
import org.habla.sample.AudioFormat;
import picocli.CommandLine.Command;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * {@code habla enrol}: adapts speech recognition to one teacher. The teacher's utterances come from WAV
 * recordings or from a microphone's PCM stream on a TCP port; the adaptation file it writes is named by
 * the {@code adaptation} param of {@code speech-recognition}.
 */
@Command(name = "enrol", mixinStandardHelpOptions = true,
        description = "Adapt speech recognition to a teacher's voice from a few utterances (recordings or a "
                + "microphone stream) and write the adaptation file that speech-recognition's 'adaptation' names.")
public final class EnrolCommand implements Callable<Integer> {

    /** The phrases a teacher is asked to say, in turn, by default: the bundled grammar's. */
    static final List<String> PROMPTS = List.of("go forward", "turn left", "turn right", "go back", "stop",
            "good dog", "bad dog", "well done", "no");
    static final int CONNECT_TIMEOUT_MS = 5000;

    @Option(names = {"-o", "--output"}, required = true, paramLabel = "FILE", description = "The adaptation file to write.")
    Path output;

    @Option(names = "--grammar", paramLabel = "FILE", description = "The JSGF grammar the teacher speaks (default: the bundled commands.gram).")
    String grammar = "";

    @Option(names = "--pcm", paramLabel = "HOST:PORT",
            description = "Read the teacher from a microphone's raw 16-bit little-endian PCM stream on this TCP port.")
    String pcm;

    @Option(names = "--rate", paramLabel = "HZ", description = "Sample rate of the --pcm stream (default ${DEFAULT-VALUE}).")
    int rateHz = 16_000;

    @Option(names = "--channels", description = "Channels of the --pcm stream (default ${DEFAULT-VALUE}).")
    int channels = 1;

    @Option(names = "--utterances", paramLabel = "N",
            description = "Utterances to take from the --pcm stream (default ${DEFAULT-VALUE}).")
    int count = 9;

    @Option(names = "--phrases", split = ",", paramLabel = "PHRASE",
            description = "What the teacher says, in order, comma-separated (repeated when they say more); default: "
                    + "go forward,turn left,turn right,go back,stop,good dog,bad dog,well done,no.")
    List<String> phrases = PROMPTS;

    @Option(names = "--force", description = "Write the adaptation even if it recognises the enrolment utterances "
            + "no better than the model as it comes.")
    boolean force;

    @Parameters(paramLabel = "WAV", arity = "0..*", description = "Recordings of the teacher (any rate and channels).")
    List<File> recordings = List.of();

    @Override
    public Integer call() throws Exception {
        if ((pcm == null) == recordings.isEmpty()) {
            System.err.println("habla enrol: give WAV recordings or --pcm HOST:PORT (one of the two)");
            return ExitCodes.USAGE_OR_CONFIG;
        }
        Enrolment enrolment = new Enrolment();
        if (pcm != null) {
            fromStream(enrolment);
        } else {
            for (File f : recordings) {
                int n = enrolment.addRecording(read(f));
                System.out.printf("%s: %d utterance%s%n", f, n, n == 1 ? "" : "s");
            }
        }
        SpeechRecognitionParams params = SpeechRecognitionParams.defaults().withGrammar(grammar);
        try {
            Enrolment.Outcome o = enrolment.write(params, phrases, output, force);
            System.out.printf("%d utterances (%.1f s of speech); of their phrases the model as it comes recognises %d, "
                    + "adapted %d%n", o.phrases(), o.frames() / 100.0, o.rightBefore(), o.rightAfter());
            if (!o.written()) {
                System.err.println("habla enrol: the adaptation recognises the teacher no better than the model as it "
                        + "comes; not written (--force writes it anyway)");
                return ExitCodes.RUNTIME_FAILURE;
            }
            System.out.printf("wrote %s; name it in the speech-recognition method's params: \"adaptation\": \"%s\"%n",
                    output, output);
            return ExitCodes.OK;
        } catch (IOException e) {
            System.err.println("habla enrol: " + e.getMessage());
            return ExitCodes.RUNTIME_FAILURE;
        }
    }

    private void fromStream(Enrolment enrolment) throws IOException {
        int colon = pcm.lastIndexOf(':');
        if (colon <= 0) {
            throw new IOException("--pcm must be HOST:PORT, was '" + pcm + "'");
        }
        try (Socket s = new Socket()) {
            s.connect(new InetSocketAddress(pcm.substring(0, colon), Integer.parseInt(pcm.substring(colon + 1))),
                    CONNECT_TIMEOUT_MS);
            InputStream in = s.getInputStream();
            int[] said = {0};
            System.out.println("say: " + phrases.get(0));
            int n = enrolment.addStream(in, new AudioFormat(rateHz, channels, 16), count, () -> {
                said[0]++;
                if (said[0] < count) {
                    System.out.println("say: " + phrases.get(said[0] % phrases.size()));
                }
            });
            System.out.printf("%d utterance%s from %s%n", n, n == 1 ? "" : "s", pcm);
        }
    }

    private static AudioChunk read(File f) throws IOException {
        try (AudioInputStream in = AudioSystem.getAudioInputStream(f)) {
            javax.sound.sampled.AudioFormat src = in.getFormat();
            javax.sound.sampled.AudioFormat pcm16 = new javax.sound.sampled.AudioFormat(src.getSampleRate(), 16,
                    src.getChannels(), true, false);
            try (AudioInputStream converted = AudioSystem.getAudioInputStream(pcm16, in)) {
                return AudioChunk.wrap(new AudioFormat(Math.round(src.getSampleRate()), src.getChannels(), 16),
                        converted.readAllBytes());
            }
        } catch (UnsupportedAudioFileException e) {
            throw new IOException(f + " is not a WAV recording HABLA can read: " + e.getMessage(), e);
        }
    }

    /** Registers {@code enrol} with {@code habla}. */
    public static final class Extension implements CommandExtension {

        @Override
        public String name() {
            return "enrol";
        }

        @Override
        public Object command() {
            return new EnrolCommand();
        }
    }
}
