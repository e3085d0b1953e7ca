package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.OptionalInt;
import org.habla.net.Expose;
import org.habla.config.HablaConfig;
import org.habla.config.InterfaceConfig;
import org.habla.net.Limits;
import org.habla.config.MethodConfig;
import org.habla.config.ParamsJson;
import org.habla.config.Reconnect;
import org.habla.config.Safety;
import org.habla.config.Source;
import org.habla.config.StatusConfig;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.LinkReport;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.Shape;
import org.habla.method.builtin.ChannelReader;
import org.habla.method.builtin.PassThrough;
import org.habla.method.builtin.RelayParams;
import org.habla.net.ControlPoint;
import org.habla.plugin.NoParams;
import org.habla.plugin.PluginRegistry;
import org.habla.sample.RecordField;
import org.junit.jupiter.api.Test;

/** An output that hands its input on shows the shape of what feeds it, through any number of hand-ons. */
class WiredShapesTest {

    /** {@code @robot.link → raw (channel) → up (pass-through) → out (pass-through, exposed)}. */
    private static MethodGraph graph() {
        RelayParams record = ParamsJson.of(RelayParams.class, "{\"kind\": \"record\"}");
        RelayParams any = RelayParams.defaults();
        MethodConfig raw = new MethodConfig("raw", "channel", Layer.SENSORS_ACTUATORS,
                Map.of("in", new Source.Channel("robot", "link")), Map.of(), record, Optional.empty(), Optional.empty());
        MethodConfig up = new MethodConfig("up", "pass-through", Layer.PROCESSING,
                Map.of("in", new Source.MethodOutput("raw", "out")), Map.of(), any, Optional.empty(), Optional.empty());
        MethodConfig out = new MethodConfig("out", "pass-through", Layer.VIRTUAL,
                Map.of("in", new Source.MethodOutput("up", "out")), Map.of(), any,
                Optional.of(new Expose("link", "127.0.0.1", 0)), Optional.empty());
        InterfaceConfig robot = new InterfaceConfig("robot", "lines-test",
                new InterfaceAddress("127.0.0.1", OptionalInt.of(9)), new NoParams(), new Reconnect(50, 200, 1_000, 5_000));
        HablaConfig config = new HablaConfig("shapes-test", Limits.DEFAULTS, new Safety(0),
                new StatusConfig("127.0.0.1", 0), List.of(robot), List.of(raw, up, out));
        PluginRegistry registry = PluginRegistry.of(List.of(new PassThrough.Provider(), new ChannelReader.Provider()),
                List.of(new LineDriver.Provider()));
        return MethodGraph.build(config, registry, EngineClock.system());
    }

    @Test
    void aSocketOfAPassThroughShowsTheFieldsOfTheRecordThatFeedsIt() throws Exception {
        try (MethodGraph g = graph()) {
            ControlPoint point = g.controlPoints().get(0);
            Output<?> out = point.outputs().get(0);
            assertThat(out.shape().recordFields()).as("the type alone knows nothing").isEmpty();

            Shape shown = point.shapeOf(out);

            assertThat(shown.form()).isEqualTo(LinkReport.class);
            assertThat(shown.fields()).containsExactly("up", "interface", "detail", "connections");
            assertThat(shown.recordFields()).extracting(RecordField::unit, RecordField::doc).first()
                    .isEqualTo(org.assertj.core.groups.Tuple.tuple("", "whether every connection the interface needs is up"));
        }
    }

    @Test
    void theMonitorSeesEveryHandOnAsWhatFeedsIt() throws Exception {
        try (MethodGraph g = graph()) {
            assertThat(g.outputs()).extracting(o -> o.methodId() + ":" + o.shape().fields())
                    .containsExactly("raw:[up, interface, detail, connections]", "up:[up, interface, detail, connections]",
                            "out:[up, interface, detail, connections]");
        }
    }
}
