package org.habla.sim.scenario;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.ObjectMapper;
import java.util.List;
import org.junit.jupiter.api.Test;

/** What a status snapshot says a run must still wait for before the teacher starts. */
class DaemonReadinessTest {

    private static final ObjectMapper JSON = new ObjectMapper();

    @Test
    void aMethodStillLoadingAndALinkDownAreWaitedFor() throws Exception {
        var status = JSON.readTree("""
                {"methods": [{"id": "speech", "ready": false}, {"id": "camera", "ready": true}],
                 "interfaces": [{"id": "aibo", "up": false}, {"id": "keys", "up": true}]}""");
        assertThat(DaemonReadiness.missing(status)).containsExactly("speech", "link:aibo");
        assertThat(DaemonReadiness.missing(JSON.readTree("""
                {"methods": [{"id": "speech", "ready": true}], "interfaces": [{"id": "aibo", "up": true}]}"""))).isEmpty();
        assertThat(DaemonReadiness.missing(JSON.readTree("{}"))).isNotEmpty();
    }

    @Test
    void aSocketWithoutAClientIsWaitedFor() throws Exception {
        var status = JSON.readTree("""
                {"sockets": [{"socket": "command", "clients": 1}, {"socket": "reward", "clients": 0},
                             {"socket": "action", "clients": 2}]}""");
        assertThat(DaemonReadiness.withoutClients(status, List.of("command", "distance_angle", "reward", "action")))
                .containsExactly("distance_angle", "reward");
        assertThat(DaemonReadiness.withoutClients(status, List.of("command", "action"))).isEmpty();
    }
}
