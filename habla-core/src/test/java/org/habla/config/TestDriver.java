package org.habla.config;

import java.util.List;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;
import org.habla.plugin.Param;
import org.habla.sample.PayloadKind;

/** A small robot driver for config tests: sonar, battery and keyboard readings; motion and sonar-power commands. */
record TestDriver(InterfaceAddress address, Params params) implements Driver {

    /** The driver's params. */
    record Params(
            @Param(value = "Number of sonar transducers", defaultValue = "16", min = 1, max = 32) int sonarCount) {
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return List.of(
                ChannelDescriptor.reading("sonar", PayloadKind.VECTOR, "m"),
                ChannelDescriptor.reading("battery", PayloadKind.NUMBER, "V"),
                ChannelDescriptor.reading("lines", PayloadKind.TEXT, ""),
                ChannelDescriptor.command("motion", PayloadKind.VECTOR, "m/s, rad/s", true),
                ChannelDescriptor.command("sonar-power", PayloadKind.NUMBER, "", false));
    }

    @Override
    public List<Connection> connections() {
        return List.of();
    }

    /** Makes {@link TestDriver}s under the name {@code robot-sim}. */
    static final class Provider implements DriverProvider<Params> {
        @Override
        public String name() {
            return "robot-sim";
        }

        @Override
        public String description() {
            return "a test robot";
        }

        @Override
        public Class<Params> paramsType() {
            return Params.class;
        }

        @Override
        public Driver create(InterfaceAddress address, Params params) {
            if (address.host().equals("unreachable.invalid")) {
                throw new IllegalArgumentException("host unreachable.invalid is refused");
            }
            return new TestDriver(address, params);
        }
    }
}
