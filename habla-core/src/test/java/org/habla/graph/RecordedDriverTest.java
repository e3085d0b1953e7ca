package org.habla.graph;

import static org.assertj.core.api.Assertions.assertThat;

import java.util.ArrayList;
import java.util.List;
import java.util.OptionalInt;
import org.habla.config.InterfaceConfig;
import org.habla.config.Reconnect;
import org.habla.driver.ChannelDescriptor;
import org.habla.driver.InterfaceAddress;
import org.habla.plugin.NoParams;
import org.habla.sample.NumberValue;
import org.habla.sample.PayloadKind;
import org.habla.sample.RecordValue;
import org.habla.sample.Sample;
import org.junit.jupiter.api.Test;

/**
 * An interface link running on a recording takes the recorded readings and link changes through its driver as it
 * takes a robot's: the readings are published on their channels, the link goes up and down as recorded, commands
 * count as written only while it is up, and the only link records are the recorded ones.
 */
class RecordedDriverTest {

    private final ManualClock clock = new ManualClock(1_000_000);
    private final RecordedDriver driver = new RecordedDriver(List.of(
            ChannelDescriptor.reading("range", PayloadKind.NUMBER, "m"),
            ChannelDescriptor.command("speed", PayloadKind.NUMBER, "m/s", false)));
    private final InterfaceLink link = new InterfaceLink(new InterfaceConfig("robot", "line",
            new InterfaceAddress("127.0.0.1", OptionalInt.of(9)), new NoParams(), Reconnect.DEFAULTS),
            driver, clock, new LinkStates());

    private Sample command(double value) {
        return new Sample(new NumberValue(value), "m.out", 1, clock.nowMicros(), false);
    }

    @Test
    void aRecordedReadingIsPublishedOnItsChannelWithItsSourceTime() {
        List<Sample> seen = new ArrayList<>();
        link.reading("range").subscribe(seen::add);
        link.start();

        driver.reading("range", new NumberValue(0.75), 42);

        assertThat(seen).singleElement().satisfies(s -> {
            assertThat(s.payload()).isEqualTo(new NumberValue(0.75));
            assertThat(s.sourceMicros()).isEqualTo(42);
            assertThat(s.producer()).isEqualTo("@robot.range");
        });
    }

    @Test
    void theLinkIsUpOnlyWhileTheRecordingSaysAndTellsEachChangeOnce() {
        List<Boolean> changes = new ArrayList<>();
        link.onLinkChange(changes::add);
        link.start();
        assertThat(link.up()).isFalse();

        driver.link(true);
        driver.link(true);
        assertThat(link.up()).isTrue();
        driver.link(false);

        assertThat(link.up()).isFalse();
        assertThat(changes).containsExactly(true, false);
    }

    @Test
    void aCommandCountsAsWrittenWhileTheRecordedLinkIsUpAndIsRefusedWhileItIsDown() {
        link.start();

        assertThat(link.command("speed", command(0.2))).isEqualTo(InterfaceCommands.Delivery.REFUSED);
        driver.link(true);
        assertThat(link.command("speed", command(0.2))).isEqualTo(InterfaceCommands.Delivery.WRITTEN);
        assertThat(link.status().get("commandsSent").asLong()).isEqualTo(1);
        assertThat(link.status().get("connections").get(0).get("replayed").booleanValue()).isTrue();
    }

    @Test
    void theOnlyLinkRecordsAreTheRecordedOnes() {
        List<Sample> records = new ArrayList<>();
        link.reading("link").subscribe(records::add);
        link.start();
        driver.link(true);
        clock.advanceMillis(3_000);
        assertThat(records).as("the engine tells no link record of its own").isEmpty();

        RecordValue recorded = RecordValue.builder().put("up", true).put("interface", "robot")
                .put("detail", "all connections up").build();
        driver.reading("link", recorded, 7);

        assertThat(records).singleElement().satisfies(s -> assertThat(s.payload()).isEqualTo(recorded));
    }
}
