package org.habla.drivers.pioneer;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** Provides the {@code pioneer} driver type. */
public final class PioneerDriverProvider implements DriverProvider<PioneerParams> {

    @Override
    public String name() {
        return "pioneer";
    }

    @Override
    public String description() {
        return "ARCOS/P2OS over TCP (default port 8101): a Pioneer 2 DX through a serial-to-TCP bridge, or MobileSim/AMRISim";
    }

    @Override
    public Class<PioneerParams> paramsType() {
        return PioneerParams.class;
    }

    @Override
    public Driver create(InterfaceAddress address, PioneerParams params) {
        return new PioneerDriver(address, params);
    }
}
