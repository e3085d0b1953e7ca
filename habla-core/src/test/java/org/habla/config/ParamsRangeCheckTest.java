package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import java.util.Map;
import org.habla.plugin.Param;
import org.junit.jupiter.api.Test;

/** The ranges a params record declares are checked by the binder, every value outside one named by its path. */
class ParamsRangeCheckTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    record Band(@Param(value = "lowest", unit = "Hz", min = 20, max = 20_000) double lowHz) {
    }

    record Params(
            @Param(value = "gain", defaultValue = "0.5", min = 0, max = 1) double gain,
            @Param(value = "period", unit = "ms", defaultValue = "100", min = 10) int periodMs,
            @Param(value = "reach", unit = "m", defaultNote = "channel metadata", greaterThan = 0) Double reachM,
            @Param(value = "weights", defaultValue = "{}", min = -1, max = 1) Map<String, Double> weights,
            @Param(value = "bands", defaultValue = "[]") List<Band> bands) {
    }

    @Test
    void valuesInsideTheirRangesBind() throws Exception {
        assertThat(errors("{\"gain\": 1, \"periodMs\": 10, \"reachM\": 0.01, \"weights\": {\"a\": -1},"
                + " \"bands\": [{\"lowHz\": 20}]}")).isEmpty();
    }

    @Test
    void everyValueOutsideItsRangeIsReportedAtItsPathTogether() throws Exception {
        assertThat(errors("{\"gain\": 1.5, \"periodMs\": 9, \"reachM\": 0, \"weights\": {\"a\": 0.5, \"b\": 2},"
                + " \"bands\": [{\"lowHz\": 100}, {\"lowHz\": 5}]}"))
                .containsExactly(
                        "$.params.bands[1].lowHz: must be within [20, 20000], was 5",
                        "$.params.gain: must be within [0, 1], was 1.5",
                        "$.params.periodMs: must be at least 10, was 9",
                        "$.params.reachM: must be greater than 0, was 0",
                        "$.params.weights.b: must be within [-1, 1], was 2");
    }

    @Test
    void aParameterLeftToItsNoteIsNotChecked() throws Exception {
        assertThat(errors("{}")).isEmpty();
    }

    @Test
    void aNumberTooLargeForADoubleIsNotFinite() throws Exception {
        assertThat(errors("{\"gain\": 1e999}")).containsExactly("$.params.gain: must be a finite number, was Infinity");
    }

    @Test
    void aValueOfTheWrongTypeIsLeftToTheBinder() throws Exception {
        assertThat(errors("{\"gain\": \"high\"}")).containsExactly("$.params.gain: must be a number, not a string (\"high\")");
    }

    private static List<String> errors(String params) throws Exception {
        ConfigErrors errors = new ConfigErrors();
        ParamsBinder.bind(JSON.readTree(params), Params.class, JsonPath.ROOT.field("params"), errors);
        return errors.sorted().stream().map(Object::toString).toList();
    }
}
