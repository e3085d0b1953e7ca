package org.habla.drivers.pioneer;

import java.time.Duration;
import java.util.List;
import java.util.Objects;
import java.util.Set;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.Connection;
import org.habla.driver.Driver;
import org.habla.driver.InterfaceAddress;
import org.habla.driver.Liveness;

/** A Pioneer reached over one ARCOS TCP connection: a simulator's port, or a serial-to-TCP bridge. */
public final class PioneerDriver implements Driver {

    /** The port MobileSim and AMRISim serve the first robot on. */
    public static final int DEFAULT_PORT = 8101;

    /**
     * ARCOS sends a SIP every 100 ms without being asked (50 ms on some firmware): three seconds without one
     * (30 missed SIPs) means the robot or its serial bridge is gone.
     */
    static final Liveness SIP_STREAM = Liveness.periodic(Duration.ofSeconds(3));

    private final int port;
    private final PioneerParams params;
    private final List<ChannelDescriptor> channels;

    public PioneerDriver(InterfaceAddress address, PioneerParams params) {
        this.port = address.portOr(DEFAULT_PORT);
        this.params = Objects.requireNonNull(params, "params");
        this.channels = PioneerChannels.describe(params);
    }

    @Override
    public List<ChannelDescriptor> channels() {
        return channels;
    }

    @Override
    public List<Connection> connections() {
        return List.of(new Connection("arcos", port, Set.of(PioneerChannels.MOTION, PioneerChannels.SONAR_POWER),
                SIP_STREAM, () -> new ArcosSession(params)));
    }
}
