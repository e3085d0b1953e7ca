package org.habla.methods.speech;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.TestInstance;

@TestInstance(TestInstance.Lifecycle.PER_CLASS)
class MoonshineTokenizerTest {

    private MoonshineTokenizer tokenizer;

    private MoonshineTokenizer tokenizer() throws IOException {
        if (tokenizer == null) {
            tokenizer = MoonshineTokenizer.load(MoonshineModelFolder.required().resolve("tokenizer.json"));
        }
        return tokenizer;
    }

    /** The token ids the model's own tokenizer library gives for these texts (Hugging Face tokenizers, once). */
    @Test
    void theGrammarsPhrasesGetTheTokensTheModelWasTrainedOn() throws IOException {
        assertThat(tokenizer().encode("go forward")).containsExactly(748, 6375);
        assertThat(tokenizer().encode("Go forward.")).containsExactly(2921, 6375, 29889);
        assertThat(tokenizer().encode("Turn left!")).containsExactly(9603, 2175, 29991);
        assertThat(tokenizer().encode("Good dog.")).containsExactly(7197, 11203, 29889);
        assertThat(tokenizer().encode("no")).containsExactly(694);
    }

    @Test
    void aCharacterOutsideTheVocabularyIsSpeltAsItsBytesAndReadBack() throws IOException {
        assertThat(tokenizer().encode("café über")).containsExactly(274, 28059, 2939);
        int[] ids = tokenizer().encode("robot \u2603 go");
        assertThat(tokenizer().decode(ids)).isEqualTo("robot \u2603 go");
    }

    @Test
    void aFileThatIsNotABpeTokenizerIsRefusedByName() throws IOException {
        Path f = Files.createTempFile("habla-tokenizer", ".json");
        Files.writeString(f, "{\"model\": {\"type\": \"Unigram\"}}");
        assertThatThrownBy(() -> MoonshineTokenizer.load(f)).hasMessageContaining(f.toString())
                .hasMessageContaining("not a BPE tokenizer");
        Files.delete(f);
    }
}
