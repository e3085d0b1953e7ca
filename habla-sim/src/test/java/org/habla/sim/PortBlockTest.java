package org.habla.sim;

import static org.assertj.core.api.Assertions.assertThat;

import java.io.BufferedReader;
import java.io.InputStreamReader;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

/** Two test JVMs that take port blocks at once never get blocks whose ports could meet. */
class PortBlockTest {

    @Test
    void anotherJvmsBlocksAreNeverNearTheOnesThisJvmHolds(@TempDir Path dir) throws Exception {
        Path holder = dir.resolve("Hold.java");
        Files.writeString(holder, """
                public class Hold {
                    public static void main(String[] a) throws Exception {
                        System.out.println(org.habla.sim.PortBlock.freeOffset() + " " + org.habla.sim.PortBlock.freeOffset());
                        System.out.flush();
                        System.in.read(); // holds its blocks until told to go
                    }
                }
                """);
        int mine = PortBlock.freeOffset();
        Process other = new ProcessBuilder(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-cp",
                System.getProperty("java.class.path"), holder.toString()).redirectErrorStream(true).start();
        try (BufferedReader out = new BufferedReader(new InputStreamReader(other.getInputStream(), StandardCharsets.UTF_8))) {
            String line = out.readLine();
            assertThat(line).as("the other JVM's blocks").matches("\\d+ \\d+");
            for (String theirs : line.split(" ")) {
                assertThat(Math.abs(Integer.parseInt(theirs) - mine)).as("their %s, mine %d", theirs, mine)
                        .isGreaterThanOrEqualTo(PortBlock.SPAN);
            }
            int next = PortBlock.freeOffset(); // taken while the other JVM holds both of its blocks
            for (String theirs : line.split(" ")) {
                assertThat(Math.abs(Integer.parseInt(theirs) - next)).as("their %s, my next %d", theirs, next)
                        .isGreaterThanOrEqualTo(PortBlock.SPAN);
            }
        } finally {
            other.getOutputStream().close();
            assertThat(other.waitFor(30, TimeUnit.SECONDS)).isTrue();
        }
    }
}
