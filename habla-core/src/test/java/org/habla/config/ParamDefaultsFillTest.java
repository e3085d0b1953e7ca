package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import java.util.Objects;
import org.habla.plugin.Param;
import org.junit.jupiter.api.Test;

/**
 * A params object's left-out keys take their declared defaults before the record is built: these records
 * refuse nulls outright, so they bind only if the loader filled every default in.
 */
class ParamDefaultsFillTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    record Port(
            @Param("the port's name") String name,
            @Param(value = "its queue", defaultValue = "8") Integer queue) {
        Port {
            Objects.requireNonNull(name, "name");
            Objects.requireNonNull(queue, "queue");
        }
    }

    record Params(
            @Param(value = "period", unit = "ms", defaultValue = "1000") Integer periodMs,
            @Param(value = "label", defaultValue = "\"step\"") String label,
            @Param(value = "ports", defaultValue = "[{\"name\": \"a\"}]") List<Port> ports,
            @Param(value = "reach", unit = "m", defaultNote = "channel metadata") Double reachM,
            @Param(value = "gain") double gain) {
        Params {
            Objects.requireNonNull(periodMs, "periodMs");
            Objects.requireNonNull(label, "label");
            Objects.requireNonNull(ports, "ports");
        }
    }

    @Test
    void aLeftOutKeyReachesTheConstructorAsItsDeclaredDefault() throws Exception {
        Params p = bind("{\"gain\": 2}");

        assertThat(p.periodMs()).isEqualTo(1000);
        assertThat(p.label()).isEqualTo("step");
    }

    @Test
    void aGivenValueIsKept() throws Exception {
        assertThat(bind("{\"gain\": 2, \"periodMs\": 50}").periodMs()).isEqualTo(50);
    }

    @Test
    void anExplicitNullIsFilledLikeALeftOutKey() throws Exception {
        assertThat(bind("{\"gain\": 2, \"label\": null}").label()).isEqualTo("step");
    }

    @Test
    void recordsInsideTheDefaultAndInsideAGivenListAreFilledToo() throws Exception {
        assertThat(bind("{\"gain\": 2}").ports()).containsExactly(new Port("a", 8));
        assertThat(bind("{\"gain\": 2, \"ports\": [{\"name\": \"b\"}, {\"name\": \"c\", \"queue\": 1}]}").ports())
                .containsExactly(new Port("b", 8), new Port("c", 1));
    }

    @Test
    void aParameterWithOnlyANoteReachesTheRecordAsNull() throws Exception {
        assertThat(bind("{\"gain\": 2}").reachM()).isNull();
    }

    @Test
    void aPrimitiveWithoutADefaultIsStillRequired() throws Exception {
        ConfigErrors errors = new ConfigErrors();

        ParamsBinder.bind(JSON.readTree("{}"), Params.class, JsonPath.ROOT.field("params"), errors);

        assertThat(errors.sorted()).extracting(Object::toString)
                .containsExactly("$.params.gain: required parameter 'gain' is missing");
    }

    @Test
    void theConfigsOwnNodeIsLeftAsItWas() throws Exception {
        JsonNode given = JSON.readTree("{\"gain\": 2}");

        ParamsBinder.bind(given, Params.class, JsonPath.ROOT.field("params"), new ConfigErrors());

        assertThat(given).isEqualTo(JSON.readTree("{\"gain\": 2}"));
    }

    @Test
    void javaCodeBindsTheRecordAndGetsTheSameDefaults() {
        Params p = ParamsJson.of(Params.class, "{\"gain\": 2}");

        assertThat(p.periodMs()).isEqualTo(1000);
        assertThat(p.ports()).containsExactly(new Port("a", 8));
    }

    @Test
    void javaCodeThatLeavesOutARequiredParameterIsRefusedWithItsPath() {
        assertThatThrownBy(() -> ParamsJson.defaults(Params.class))
                .isInstanceOf(IllegalArgumentException.class)
                .hasMessageContaining("$.params.gain: required parameter 'gain' is missing");
    }

    private static Params bind(String params) throws Exception {
        ConfigErrors errors = new ConfigErrors();
        var bound = ParamsBinder.bind(JSON.readTree(params), Params.class, JsonPath.ROOT.field("params"), errors);
        assertThat(errors.sorted()).isEmpty();
        return (Params) bound.orElseThrow();
    }
}
