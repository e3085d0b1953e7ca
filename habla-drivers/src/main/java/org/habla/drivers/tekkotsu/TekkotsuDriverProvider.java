package org.habla.drivers.tekkotsu;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** The provider of the {@code tekkotsu} driver type: a Sony Aibo ERS-7 through its Tekkotsu servers. */
public final class TekkotsuDriverProvider implements DriverProvider<TekkotsuParams> {

    @Override
    public String name() {
        return "tekkotsu";
    }

    @Override
    public String description() {
        return "Sony Aibo ERS-7 through the Tekkotsu 4.0+ servers (world state, walk, head, e-stop, microphone, "
                + "speaker, raw camera over TCP, controller menu).";
    }

    @Override
    public Class<TekkotsuParams> paramsType() {
        return TekkotsuParams.class;
    }

    /** The host comes from {@code address}; every port from the params (an address port is ignored). */
    @Override
    public Driver create(InterfaceAddress address, TekkotsuParams params) {
        return new TekkotsuDriver(params == null ? TekkotsuParams.defaults() : params);
    }
}
