package org.habla.sim.cli;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.DataInputStream;
import java.io.IOException;
import java.io.PrintWriter;
import java.io.StringWriter;
import java.net.InetAddress;
import java.net.Socket;
import java.nio.file.Path;
import java.util.HexFormat;
import java.util.ServiceLoader;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import org.habla.command.CommandExtension;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;
import picocli.CommandLine;

class SimPioneerCommandTest {

    @Test
    void habladiscoversTheSimCommandThroughItsExtensionPoint() {
        assertThat(ServiceLoader.load(CommandExtension.class).stream().map(p -> p.get().name()))
                .contains("sim");
    }

    @Test
    void simPioneerServesARobotOnThePortsItPrintsForTheGivenSimTime() throws Exception {
        StringWriter out = new StringWriter();
        CommandLine cli = new CommandLine(new SimCommand()).setOut(new PrintWriter(out, true));
        CompletableFuture<Integer> exit = CompletableFuture.supplyAsync(() -> cli.execute("pioneer", "--port", "0",
                "--mic-port", "0", "--keys-port", "0", "--truth-port", "0", "--speed", "20", "--duration", "60",
                "--teacher", "off"));
        int port = -1;
        for (long end = System.nanoTime() + 30_000_000_000L; port < 0 && System.nanoTime() < end; ) {
            Matcher m = Pattern.compile("arcos 127\\.0\\.0\\.1:(\\d+)").matcher(out.toString());
            if (m.find()) {
                port = Integer.parseInt(m.group(1));
            } else {
                Thread.sleep(50);
            }
        }
        assertThat(port).as("the ARCOS port printed in %s", out).isPositive();
        try (Socket s = new Socket(InetAddress.getLoopbackAddress(), port)) {
            s.setSoTimeout(5_000);
            s.getOutputStream().write(HexFormat.of().parseHex("fafb03000000"));
            byte[] echo = new byte[6];
            new DataInputStream(s.getInputStream()).readFully(echo);
            assertThat(HexFormat.of().formatHex(echo)).isEqualTo("fafb03000000");
        }
        assertThat(exit.get(60, TimeUnit.SECONDS)).isZero();
        assertThat(out.toString()).contains("simulated Pioneer in 'pioneer-room'").contains("ground-truth 127.0.0.1:");
    }

    @Test
    void badOptionsExitWithTheUsageCode(@TempDir Path dir) throws IOException {
        StringWriter err = new StringWriter();
        CommandLine cli = new CommandLine(new SimCommand()).setErr(new PrintWriter(err, true));
        assertThat(cli.execute("pioneer", "--teacher", "maybe")).isEqualTo(2);
        assertThat(cli.execute("pioneer", "--speed", "0.5")).isEqualTo(2);
        assertThat(cli.execute("pioneer", "--world", dir.resolve("missing.json").toString())).isEqualTo(2);
        java.nio.file.Files.writeString(dir.resolve("typo.json"), "{\"name\":\"x\",\"arena\":{\"walls\":[]},"
                + "\"target\":{\"xM\":1,\"yM\":1,\"radiusM\":0.1},\"robot\":{\"xM\":0,\"yM\":0},\"techer\":{}}");
        assertThat(cli.execute("pioneer", "--world", dir.resolve("typo.json").toString())).isEqualTo(2);
        assertThat(err.toString()).contains("--teacher must be on or off").contains("speed must be")
                .contains("$.techer is not a known key");
    }
}
