package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.OutputStream;
import java.net.InetAddress;
import java.net.ServerSocket;
import java.net.Socket;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import org.habla.cli.Habla;
import org.habla.sample.AudioChunk;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/**
 * {@code habla enrol} takes a teacher's utterances from a microphone's PCM stream on a loopback port,
 * writes an adaptation file, and a {@code speech-recognition} method that names it in
 * {@code adaptation} hears that teacher through the adapted model, about as well as the model as it
 * comes (Sphinx-4's own MLLR left the adapted model hearing almost nothing). The teacher: espeak-ng's
 * Caribbean English, a voice never used for tuning (the kept part of the evaluation set), saying its
 * thirteen items. How much adaptation helps on utterances it did not see is measured by
 * {@code bench/run speech}.
 */
class EnrolCommandTest {

    @Test
    void aTeacherEnrolsFromAMicrophoneStreamAndIsThenHeardThroughTheAdaptedModel(@TempDir Path dir) throws Exception {
        EvalSet.Voice teacher = EvalSet.read(HeldOutVoicesTest.SUBSET).stream()
                .filter(v -> v.name().equals("espeak-caribbean")).findFirst().orElseThrow();
        AudioChunk stream = Utterances.readWav(teacher.stream("clean"));
        Path file = dir.resolve("teacher.mllr");
        try (ServerSocket mic = new ServerSocket(0, 1, InetAddress.getLoopbackAddress())) {
            Thread.ofPlatform().daemon().start(() -> {
                try (Socket s = mic.accept(); OutputStream out = s.getOutputStream()) {
                    out.write(stream.pcm());
                } catch (Exception e) {
                    // the command hung up once it had its utterances
                }
            });
            String said = String.join(",", teacher.items().stream().map(EvalSet.Item::text).toList());
            int code = Habla.execute("enrol", "--pcm", "127.0.0.1:" + mic.getLocalPort(), "--utterances", "13",
                    "--phrases", said, "--force", "--output", file.toString());
            assertThat(code).isZero();
        }
        // one regression class, three feature streams of 13 coefficients: Sphinx's MLLR file
        assertThat(Files.readAllLines(file).subList(0, 3)).containsExactly("1", "3", "13");

        Record audio = org.habla.methods.audio.AudioProcessingParams.defaults();
        SpeechRecognitionParams plain = SpeechRecognitionParams.defaults();
        SpeechChain before = SpeechChain.of(audio, plain.withMinConfidence(0));
        SpeechChain after = SpeechChain.of(audio, plain.withMinConfidence(0).withAdaptation(file.toString()));
        List<SpeechChain.Heard> heardBefore = before.run(stream, 32);
        List<SpeechChain.Heard> heardAfter = after.run(stream, 32);
        System.out.printf("speech-recognition: before enrolment %s%n  after %s%n", heardBefore, heardAfter);
        StreamScore scoreBefore = new StreamScore();
        scoreBefore.add(teacher.name(), teacher.items(), heardBefore, EvalSet.GRAMMAR);
        StreamScore scoreAfter = new StreamScore();
        scoreAfter.add(teacher.name(), teacher.items(), heardAfter, EvalSet.GRAMMAR);
        assertThat(heardAfter.stream().map(SpeechChain.Heard::confidence).toList())
                .as("the adapted model scores the teacher's utterances differently")
                .isNotEqualTo(heardBefore.stream().map(SpeechChain.Heard::confidence).toList());
        assertThat(scoreBefore.inGrammarRight).isGreaterThanOrEqualTo(4);
        assertThat(scoreAfter.inGrammarRight).as("phrases heard right after enrolment (before: %d)",
                scoreBefore.inGrammarRight).isGreaterThanOrEqualTo(scoreBefore.inGrammarRight - 2);
    }

    @Test
    void enrolmentRefusesTooFewUtterances(@TempDir Path dir) {
        Path file = dir.resolve("x.mllr");
        Enrolment e = new Enrolment();
        assertThat(Habla.execute("enrol", "--output", file.toString())).isEqualTo(2);
        assertThat(org.assertj.core.api.Assertions.catchThrowable(
                () -> e.write(SpeechRecognitionParams.defaults(), List.of("stop"), file, true))).hasMessageContaining("MIN_UTTERANCES");
        assertThat(List.of(file)).noneMatch(Files::exists);
    }
}
