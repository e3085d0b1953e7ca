package org.habla.drivers.pioneer;

import com.fasterxml.jackson.databind.node.ArrayNode;
import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.util.List;
import org.habla.driver.ChannelDescriptor;
import org.habla.sample.PayloadKind;

/** The channels of a {@code pioneer} interface, with the robot's facts as metadata in SI units. */
final class PioneerChannels {

    static final String SONAR = "sonar";
    static final String ODOMETRY = "odometry";
    static final String BATTERY = "battery";
    static final String BUMPERS = "bumpers";
    static final String STALL = "stall";
    static final String STATUS = "status";
    static final String MOTION = "motion";
    static final String SONAR_POWER = "sonar-power";

    private PioneerChannels() {
    }

    static List<ChannelDescriptor> describe(PioneerParams p) {
        ObjectNode geometry = geometry(p);
        ObjectNode bumperCounts = JsonNodeFactory.instance.objectNode()
                .put("frontCount", p.frontBumpers()).put("rearCount", p.rearBumpers());
        return List.of(
                ChannelDescriptor.reading(SONAR, PayloadKind.VECTOR, "m").withMetadata(sonarMetadata(p)),
                ChannelDescriptor.reading(ODOMETRY, PayloadKind.RECORD, "m, rad, m/s, rad/s").withMetadata(geometry),
                ChannelDescriptor.reading(BATTERY, PayloadKind.NUMBER, "V"),
                ChannelDescriptor.reading(BUMPERS, PayloadKind.RECORD, "").withMetadata(bumperCounts),
                ChannelDescriptor.reading(STALL, PayloadKind.RECORD, ""),
                ChannelDescriptor.reading(STATUS, PayloadKind.RECORD, "").withMetadata(geometry),
                ChannelDescriptor.command(MOTION, PayloadKind.VECTOR, "m/s, rad/s", true).withMetadata(geometry),
                ChannelDescriptor.command(SONAR_POWER, PayloadKind.NUMBER, "", false));
    }

    static ObjectNode geometry(PioneerParams p) {
        return JsonNodeFactory.instance.objectNode()
                .put("radiusM", p.radiusM())
                .put("widthM", p.widthM())
                .put("lengthM", p.lengthM())
                .put("maxVelMps", p.maxVelMps())
                .put("maxRotVelRadps", p.maxRotVelRadps());
    }

    static ObjectNode sonarMetadata(PioneerParams p) {
        ObjectNode m = JsonNodeFactory.instance.objectNode();
        ArrayNode poses = m.putArray("poses");
        for (SonarPose pose : p.sonarPoses()) {
            poses.addObject().put("xM", pose.xM()).put("yM", pose.yM()).put("thetaRad", pose.thetaRad());
        }
        m.put("maxRangeM", p.maxRangeM());
        m.put("minRangeM", p.minRangeM());
        m.put("beamWidthRad", p.beamWidthRad());
        return m;
    }
}
