package org.habla.drivers.lines;

import java.util.List;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.Liveness;
import org.habla.sample.PayloadKind;

/** A device that speaks in UTF-8 lines over one TCP connection: a keyboard in a terminal, a simple sensor. */
public final class TextLinesDriver implements Driver {

    /** The port the teacher's keyboard is served on in the Pioneer scenario. */
    public static final int DEFAULT_PORT = 8111;
    /** The reading channel: one text per line received. */
    public static final String LINES = "lines";
    /** The command channel: one text written as one line. */
    public static final String SEND = "send";

    private static final List<ChannelDescriptor> CHANNELS = List.of(
            ChannelDescriptor.reading(LINES, PayloadKind.TEXT, ""),
            ChannelDescriptor.command(SEND, PayloadKind.TEXT, "", false));

    private final int port;
    private final TextLinesParams params;

    public TextLinesDriver(InterfaceAddress address, TextLinesParams params) {
        this.port = address.portOr(DEFAULT_PORT);
        this.params = params;
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return CHANNELS;
    }

    @Override
    public List<Connection> connections() {
        // A keyboard, a bumper, a door contact: silence is normal; only TCP tells that the peer is gone.
        return List.of(new Connection("lines", port, Set.of(SEND), Liveness.quiet(), () -> new TextLinesSession(params)));
    }
}
