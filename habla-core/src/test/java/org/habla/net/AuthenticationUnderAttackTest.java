package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.IOException;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.Random;
import java.util.concurrent.CopyOnWriteArrayList;
import java.util.concurrent.ExecutorService;
import java.util.concurrent.Executors;
import java.util.concurrent.TimeUnit;
import java.util.concurrent.atomic.AtomicBoolean;
import java.util.concurrent.atomic.AtomicInteger;
import java.util.function.BooleanSupplier;
import org.habla.sample.NumberValue;
import org.habla.security.AuditEntry;
import org.habla.security.AuditLog;
import org.habla.security.Credentials;
import org.habla.security.LoginThrottle;
import org.habla.security.PortAccess;
import org.habla.security.PortSecurity;
import org.habla.security.Role;
import org.junit.jupiter.api.AfterEach;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

/**
 * A socket that requires authentication while others try to get in without a token: they never cost an
 * authenticated client its place, they hold no memory, and each of their attempts is counted and audited.
 */
@Timeout(60)
class AuthenticationUnderAttackTest {

    private static final String DRIVER_TOKEN = "driver-token-0123456789";
    private static final String VIEWER_TOKEN = "viewer-token-0123456789";
    private static final Credentials CREDENTIALS = Credentials.of(Map.of(
            "mdb", Map.entry(DRIVER_TOKEN, Map.of("tracker", Role.COMMAND)),
            "viewer", Map.entry(VIEWER_TOKEN, Map.of("*", Role.READ))), null);

    private final List<AutoCloseable> open = new ArrayList<>();
    private final List<AuditEntry> audited = new CopyOnWriteArrayList<>();
    private final FakeControlPoint point = FakeControlPoint.commanded(0);
    private ControlServer server;

    /** Four client places; a client idle for 200 ms may be evicted by a new client. */
    private void serve() throws IOException {
        AuditLog audit = AuditLog.withoutFile();
        audit.addListener(audited::add);
        server = new ControlServer(point, new Expose(point.name(), "127.0.0.1", 0),
                new Limits(4_096, 1 << 20, 4, 8).withDeadlines(60_000, 10_000, 200), BlockBudget.of("test", 8 << 20),
                new PortSecurity(PortAccess.authenticated(point.name(), CREDENTIALS), audit, null));
        server.start();
        open.add(server);
    }

    private TestClient connect(String from) throws IOException {
        TestClient c = new TestClient(server.port(), from);
        open.add(c);
        assertThat(c.next().header().path("auth").asText()).isEqualTo("required");
        return c;
    }

    private TestClient authenticated(String client, String token) throws IOException {
        TestClient c = connect("127.0.0.1");
        c.send("{\"op\":\"auth\",\"client\":\"" + client + "\",\"token\":\"" + token + "\"}");
        Frame hello = c.next();
        assertThat(hello.header().toString()).contains("\"type\":\"hello\"", "\"client\":\"" + client + "\"");
        return c;
    }

    @AfterEach
    void closeAll() throws Exception {
        for (AutoCloseable c : open.reversed()) {
            c.close();
        }
    }

    @Test
    void loginsWithoutATokenInFlightNeverCostAGoodClientItsPlace() throws Exception {
        serve();
        TestClient viewer = authenticated("viewer", VIEWER_TOKEN); // then idle, past limits.evictableIdleMs
        AtomicBoolean attacking = new AtomicBoolean(true);
        AtomicInteger attempts = new AtomicInteger();
        ExecutorService attackers = Executors.newVirtualThreadPerTaskExecutor();
        try {
            for (int i = 0; i < 20; i++) {
                attackers.submit(() -> attackWithoutAToken(attacking, attempts));
            }
            await("twenty attempts are under way", () -> attempts.get() >= 20);
            for (int i = 0; i < 24; i++) {
                try (TestClient driver = authenticated("mdb", DRIVER_TOKEN)) {
                    driver.send("{\"op\":\"ping\",\"id\":" + i + "}");
                    assertThat(driver.next("pong").header().path("id").asInt()).isEqualTo(i);
                }
            }
        } finally {
            attacking.set(false);
            attackers.shutdown();
            assertThat(attackers.awaitTermination(20, TimeUnit.SECONDS)).isTrue();
        }
        point.emit("distance", new NumberValue(4));
        assertThat(viewer.next().header().toString()).as("the idle viewer kept its place")
                .contains("\"type\":\"sample\"");
        assertThat(server.stats().path("evicted").asLong()).isZero();
        assertThat(server.stats().path("refused").asLong()).isZero();
    }

    /** One attacker: auth lines without a token, one after the other, each from an address of its own. */
    private Void attackWithoutAToken(AtomicBoolean attacking, AtomicInteger attempts) throws IOException {
        while (attacking.get()) {
            int n = attempts.incrementAndGet();
            try (TestClient c = new TestClient(server.port(), "127.0." + (1 + n / 250) + "." + (2 + n % 250))) {
                c.next();
                c.send("{\"op\":\"auth\",\"client\":\"mdb\"}");
                for (Frame f = c.next(); f != null; f = c.next()) {
                    // read to the refusal and the end
                }
            } catch (IOException | AssertionError e) {
                // refused or reset: the next attempt
            }
        }
        return null;
    }

    @Test
    void failedLoginsAreLimitedPerAddressAndEveryAttemptIsCountedAndAudited() throws Exception {
        serve();
        int attempts = 30;
        List<String> answers = new CopyOnWriteArrayList<>();
        try (ExecutorService guessers = Executors.newVirtualThreadPerTaskExecutor()) {
            for (int i = 0; i < attempts; i++) { // at once, from one address
                String guess = "{\"op\":\"auth\",\"client\":\"mdb\",\"token\":\"guess-" + i + "-0123456789\"}";
                guessers.submit(() -> {
                    try (TestClient c = new TestClient(server.port(), "127.0.0.9")) {
                        c.next();
                        c.send(guess);
                        answers.add(c.next().header().path("code").asText());
                    }
                    return null;
                });
            }
            TestClient good = authenticated("mdb", DRIVER_TOKEN); // meanwhile, from another address
            good.send("{\"op\":\"ping\",\"id\":1}");
            assertThat(good.next("pong")).isNotNull();
        }
        assertThat(answers).hasSize(attempts).containsOnly("auth_failed", "auth_throttled");
        long checked = answers.stream().filter("auth_failed"::equals).count();
        assertThat(checked).as("checked: the address's burst, and what came back meanwhile")
                .isBetween(1L, (long) LoginThrottle.BURST + 1);
        assertThat(server.stats().path("authFailures").asLong()).isEqualTo(attempts);
        assertThat(server.stats().path("authThrottled").asLong()).isEqualTo(attempts - checked);
        assertThat(audited).filteredOn(e -> e.address().startsWith("127.0.0.9:")).hasSize(attempts)
                .allSatisfy(e -> assertThat(e.action()).isEqualTo("auth"));
    }

    @Test
    void aBlockSentBeforeAuthenticatingIsNeverBuffered() throws Exception {
        serve();
        TestClient c = connect("127.0.0.1");
        c.send("{\"op\":\"write\",\"input\":\"action\",\"kind\":\"text\",\"bytes\":1048576}");
        try {
            c.sendRaw(new byte[600_000]);
        } catch (IOException closedMeanwhile) {
            // the daemon may close before taking it all; its error line is still to be read
        }
        Frame refused = c.next();
        assertThat(refused.header().path("code").asText()).as(refused.header().toString()).isEqualTo("auth_required");
        assertThat(server.blockBytesInFlight()).isZero();
        assertThat(server.stats().path("blockBytes").asLong()).isZero();
        assertThat(c.next()).as("the connection is closed").isNull();
    }

    @Test
    void garbageBeforeAuthenticatingGetsOneAuthRequiredLineThenTheConnectionCloses() throws Exception {
        serve();
        TestClient c = connect("127.0.0.1");
        byte[] garbage = new byte[65_536];
        new Random(7).nextBytes(garbage);
        try {
            c.sendRaw(garbage);
        } catch (IOException closedMeanwhile) {
            // the daemon may close before taking it all
        }
        List<String> lines = new ArrayList<>();
        for (Frame f = c.next(); f != null && lines.size() < 1_000; f = c.next()) {
            lines.add(f.header().path("code").asText());
        }
        assertThat(lines).containsExactly("auth_required");
    }

    @Test
    void anAuthLineWithoutStringsAndASecondAuthLineAreAnsweredAsTheProtocolSays() throws Exception {
        serve();
        TestClient c = connect("127.0.0.1");
        c.send("{\"op\":\"auth\",\"client\":\"mdb\",\"token\":12345}");
        Frame refused = c.next();
        assertThat(refused.header().path("code").asText()).isEqualTo("auth_failed");
        assertThat(refused.header().path("message").asText()).contains("\"client\" and \"token\" strings");
        TestClient mdb = authenticated("mdb", DRIVER_TOKEN);
        mdb.send("{\"op\":\"auth\",\"client\":\"viewer\",\"token\":\"" + VIEWER_TOKEN + "\",\"id\":1}");
        Frame again = mdb.next("error");
        assertThat(again.header().path("code").asText()).isEqualTo("already_authenticated");
        mdb.send("{\"op\":\"ping\",\"id\":2}");
        assertThat(mdb.next("pong").header().path("id").asInt()).as("the connection stays, still mdb's").isEqualTo(2);
    }

    private static void await(String what, BooleanSupplier condition) throws InterruptedException {
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (!condition.getAsBoolean()) {
            if (System.nanoTime() > until) {
                throw new AssertionError("timed out waiting until " + what);
            }
            Thread.sleep(5);
        }
    }
}
