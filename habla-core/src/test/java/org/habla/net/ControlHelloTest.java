package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.List;
import java.util.Map;
import org.habla.net.Limits;
import org.habla.method.Input;
import org.habla.method.Layer;
import org.habla.method.Output;
import org.habla.method.OutputPort;
import org.habla.method.Shape;
import org.habla.method.VirtualMethod;
import org.habla.sample.Payload;
import org.habla.sample.RecordForm;
import org.habla.sample.RecordLayout;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

/** The hello names each declared field of a typed record output with its type, unit, frame and meaning. */
class ControlHelloTest {

    record Sighting(double distanceM, boolean seen) implements RecordForm {
        static final RecordLayout<Sighting> LAYOUT = RecordLayout.of(Sighting.class)
                .number("distanceM", Sighting::distanceM).unit("m").frame("from the robot's edge").doc("how far")
                .flag("seen", Sighting::seen).doc("whether it is in view")
                .build();

        @Override
        public RecordLayout<Sighting> layout() {
            return LAYOUT;
        }
    }

    static final class Sights extends VirtualMethod {
        Sights() {
            output(OutputPort.of("sighting", RecordValue.class, Shape.record("the target", Sighting.LAYOUT)));
            output(OutputPort.of("plain", RecordValue.class, Shape.record("a device's message", "state")));
        }
    }

    /** A control point of the {@code Sights} method, shown as the engine would show it. */
    private static ControlPoint point() {
        Sights method = new Sights();
        return new ControlPoint() {
            public String name() {
                return "sights";
            }

            public String methodId() {
                return "sights";
            }

            public Layer layer() {
                return Layer.VIRTUAL;
            }

            public List<Output<?>> outputs() {
                return method.outputs();
            }

            public List<Input<?>> controlInputs() {
                return List.of();
            }

            public Map<String, Sample> latest() {
                return Map.of();
            }

            public boolean stale() {
                return false;
            }

            public Subscription subscribe(Listener listener) {
                return () -> { };
            }

            public void write(Input<?> input, Payload value) {
            }

            public void writerLeft() {
            }
        };
    }

    @Test
    void aTypedRecordOutputListsItsFieldsWithUnitFrameAndMeaning() {
        Frame hello = ControlHello.full(point(), Limits.DEFAULTS, null, null);

        assertThat(hello.header().path("outputs").get(0).toString()).isEqualTo("{\"name\":\"sighting\",\"kind\":\"record\","
                + "\"unit\":\"\",\"fields\":[\"distanceM\",\"seen\"],\"doc\":\"the target\",\"fieldInfo\":["
                + "{\"name\":\"distanceM\",\"type\":\"number\",\"unit\":\"m\",\"frame\":\"from the robot's edge\","
                + "\"doc\":\"how far\",\"optional\":false},"
                + "{\"name\":\"seen\",\"type\":\"boolean\",\"unit\":\"\",\"frame\":\"\",\"doc\":\"whether it is in view\","
                + "\"optional\":false}]}");
    }

    @Test
    void aPlainRecordOutputIsDescribedAsBeforeWithoutFieldInfo() {
        Frame hello = ControlHello.full(point(), Limits.DEFAULTS, null, null);

        assertThat(hello.header().path("outputs").get(1).toString()).isEqualTo("{\"name\":\"plain\",\"kind\":\"record\","
                + "\"unit\":\"\",\"fields\":[\"state\"],\"doc\":\"a device's message\"}");
    }
}
