package org.habla.methods.virtual;

import static org.assertj.core.api.Assertions.assertThat;

import org.habla.method.MethodHarness;
import org.habla.sample.RecordValue;
import org.junit.jupiter.api.Test;

class LinkStateTest {

    private static RecordValue link(boolean up) {
        return RecordValue.builder().put("up", up).put("interface", "robot")
                .put("detail", up ? "all connections up" : "arcos down: connection refused").build();
    }

    @Test
    void sinceMsCountsFromTheLastChangeOfTheLink() {
        MethodHarness h = MethodHarness.started("link", new LinkState(LinkStateParams.defaults()));
        h.push("link", link(true)).advanceMillis(1000).push("link", link(true));
        RecordValue r = (RecordValue) h.last("link");
        assertThat(r.get("connected").booleanValue()).isTrue();
        assertThat(r.get("stale").booleanValue()).isFalse();
        assertThat(r.number("sinceMs")).isEqualTo(1000);
        h.advanceMillis(500).push("link", link(false));
        r = (RecordValue) h.last("link");
        assertThat(r.get("connected").booleanValue()).isFalse();
        assertThat(r.number("sinceMs")).isEqualTo(0);
        assertThat(r.text("detail")).contains("arcos down");
        assertThat(r.text("interface")).isEqualTo("robot");
    }

    @Test
    void silenceMakesTheStateStaleOnceAndFreshNewsClearsIt() {
        MethodHarness h = MethodHarness.started("link", new LinkState(new LinkStateParams(1000)));
        h.advanceMillis(3000);
        assertThat(h.values("link")).as("nothing before the first record").isEmpty();
        h.push("link", link(true)).advanceMillis(900);
        assertThat(h.values("link")).hasSize(1);
        h.advanceMillis(400);
        RecordValue r = (RecordValue) h.last("link");
        assertThat(r.get("stale").booleanValue()).isTrue();
        assertThat(r.get("connected").booleanValue()).isTrue();
        h.advanceMillis(5000);
        assertThat(h.values("link")).hasSize(2);
        h.push("link", link(true));
        assertThat(((RecordValue) h.last("link")).get("stale").booleanValue()).isFalse();
    }

    @Test
    void theStateOfEachConnectionIsPassedOn() {
        MethodHarness h = MethodHarness.started("link", new LinkState(LinkStateParams.defaults()));
        com.fasterxml.jackson.databind.node.ObjectNode each =
                com.fasterxml.jackson.databind.node.JsonNodeFactory.instance.objectNode()
                        .put("worldstate", true).put("controller", false);
        h.push("link", RecordValue.builder().put("up", true).put("interface", "aibo")
                .put("detail", "controller (optional) down: Connection refused").set("connections", each).build());
        RecordValue r = (RecordValue) h.last("link");
        assertThat(r.get("connected").booleanValue()).isTrue();
        assertThat(r.get("connections").get("worldstate").booleanValue()).isTrue();
        assertThat(r.get("connections").get("controller").booleanValue()).isFalse();
    }

    @Test
    void aRecordWithoutUpIsIgnored() {
        LinkState m = new LinkState(LinkStateParams.defaults());
        MethodHarness h = MethodHarness.started("link", m);
        h.push("link", RecordValue.builder().put("up", "yes").build());
        assertThat(h.values("link")).isEmpty();
        assertThat(m.malformed()).isEqualTo(1);
    }
}
