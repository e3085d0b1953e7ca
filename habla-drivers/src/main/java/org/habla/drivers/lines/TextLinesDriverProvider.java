package org.habla.drivers.lines;

import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.DriverProvider;

/** Provides the {@code text-lines} driver type. */
public final class TextLinesDriverProvider implements DriverProvider<TextLinesParams> {

    @Override
    public String name() {
        return "text-lines";
    }

    @Override
    public String description() {
        return "UTF-8 lines over TCP (default port 8111), e.g. a teacher's keyboard through 'nc -l 8111'";
    }

    @Override
    public Class<TextLinesParams> paramsType() {
        return TextLinesParams.class;
    }

    @Override
    public Driver create(InterfaceAddress address, TextLinesParams params) {
        return new TextLinesDriver(address, params);
    }
}
