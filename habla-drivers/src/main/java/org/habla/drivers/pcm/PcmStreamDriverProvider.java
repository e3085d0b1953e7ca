package org.habla.drivers.pcm;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** Provides the {@code pcm-stream} driver type. */
public final class PcmStreamDriverProvider implements DriverProvider<PcmStreamParams> {

    @Override
    public String name() {
        return "pcm-stream";
    }

    @Override
    public String description() {
        return "Raw PCM audio over TCP (default port 8110), e.g. 'arecord -f S16_LE -r 16000 -c 1 -t raw | nc -l 8110'";
    }

    @Override
    public Class<PcmStreamParams> paramsType() {
        return PcmStreamParams.class;
    }

    @Override
    public Driver create(InterfaceAddress address, PcmStreamParams params) {
        return new PcmStreamDriver(address, params);
    }
}
