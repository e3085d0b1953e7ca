package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.nio.file.Path;
import org.habla.plugin.Param;
import org.junit.jupiter.api.Test;

/** File params: a relative path is taken from the config's folder, so a config and its files move together. */
class FileParamTest {

    record WithFile(@Param(value = "a grammar", file = true) String grammar, @Param("a name") String name) {
    }

    @Test
    void aRelativeFileIsTakenFromTheConfigsFolderAndOtherTextIsLeftAlone() throws Exception {
        ConfigErrors errors = new ConfigErrors();
        var node = new ObjectMapper().readTree("{\"grammar\": \"grammars/a.gram\", \"name\": \"grammars/b\"}");
        WithFile w = (WithFile) ParamsBinder.bind(node, WithFile.class, JsonPath.ROOT, errors, Path.of("/etc/habla"))
                .orElseThrow();
        assertThat(w.grammar()).isEqualTo(Path.of("/etc/habla/grammars/a.gram").toString());
        assertThat(w.name()).isEqualTo("grammars/b");
    }

    @Test
    void anAbsoluteFileStaysAsGiven() throws Exception {
        ConfigErrors errors = new ConfigErrors();
        var node = new ObjectMapper().readTree("{\"grammar\": \"/srv/a.gram\"}");
        WithFile w = (WithFile) ParamsBinder.bind(node, WithFile.class, JsonPath.ROOT, errors, Path.of("/etc/habla"))
                .orElseThrow();
        assertThat(w.grammar()).isEqualTo("/srv/a.gram");
    }
}
