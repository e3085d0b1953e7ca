package org.habla.drivers.iface;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** Makes drivers of type {@code habla}: HABLA's own interface protocol. */
public final class InterfaceProtocolDriverProvider implements DriverProvider<InterfaceParams> {

    /** The port an interface program listens on when the address names none. */
    public static final int DEFAULT_PORT = 7600;

    @Override
    public String name() {
        return "habla";
    }

    @Override
    public String description() {
        return "HABLA's own interface protocol (habla-interface/1): a program on new hardware announces its "
                + "channels, streams readings and takes commands, as JSON lines over TCP";
    }

    @Override
    public Class<InterfaceParams> paramsType() {
        return InterfaceParams.class;
    }

    @Override
    public Driver create(InterfaceAddress address, InterfaceParams params) {
        return new InterfaceProtocolDriver(address.portOr(DEFAULT_PORT), params);
    }
}
