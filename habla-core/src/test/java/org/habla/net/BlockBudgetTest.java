package org.habla.net;

import static java.nio.charset.StandardCharsets.UTF_8;
import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatThrownBy;

import java.io.ByteArrayInputStream;
import java.io.IOException;
import java.io.PipedInputStream;
import java.io.PipedOutputStream;
import java.util.concurrent.CompletableFuture;
import java.util.concurrent.TimeUnit;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(30)
class BlockBudgetTest {

    @Test
    void aReservationMustFitTheBudgetAndEveryEnclosingOne() throws Exception {
        BlockBudget process = BlockBudget.of("limits.processBlockBudgetBytes", 100);
        BlockBudget a = process.child("limits.socketBlockBudgetBytes", 80);
        BlockBudget b = process.child("limits.socketBlockBudgetBytes", 80);
        a.reserve(60);
        assertThatThrownBy(() -> a.reserve(30)).isInstanceOf(FrameException.class)
                .hasMessageContaining("limits.socketBlockBudgetBytes=80");
        assertThatThrownBy(() -> b.reserve(50)).isInstanceOf(FrameException.class)
                .hasMessageContaining("limits.processBlockBudgetBytes=100");
        assertThat(b.reserved()).as("a refused reservation leaves nothing behind").isZero();
        b.reserve(40);
        assertThat(process.reserved()).isEqualTo(100);
        a.release(60);
        b.release(40);
        assertThat(process.reserved()).isZero();
    }

    @Test
    void aDeclaredBlockReservesOnlyWhatHasArrivedThenGivesItBack() throws Exception {
        BlockBudget budget = BlockBudget.of("limits.socketBlockBudgetBytes", 64L << 20);
        PipedOutputStream wire = new PipedOutputStream();
        PipedInputStream in = new PipedInputStream(wire, 1 << 16);
        FrameReader reader = new FrameReader(in, 1_024, 8 << 20, budget);
        CompletableFuture<Frame> frame = CompletableFuture.supplyAsync(() -> {
            try {
                return reader.read();
            } catch (IOException e) {
                throw new IllegalStateException(e);
            }
        });
        wire.write("{\"bytes\":8388608}\n".getBytes(UTF_8));
        wire.write(new byte[10]);
        wire.flush();
        long until = System.nanoTime() + TimeUnit.SECONDS.toNanos(10);
        while (budget.reserved() == 0 && System.nanoTime() < until) {
            Thread.sleep(5);
        }
        assertThat(budget.reserved()).as("room for the first bytes, not for the 8 MiB declared")
                .isEqualTo(LineFramer.FIRST_BLOCK_BYTES);
        assertThat(reader.frameSinceNanos()).as("a frame is under way").isNotZero();
        byte[] rest = new byte[8_388_608 - 10];
        rest[rest.length - 1] = 7;
        wire.write(rest);
        wire.flush();
        Frame f = frame.get(10, TimeUnit.SECONDS);
        assertThat(f.body()).hasSize(8_388_608);
        assertThat(f.body()[8_388_607]).isEqualTo((byte) 7);
        assertThat(budget.reserved()).as("the whole block has left the budget").isZero();
        assertThat(reader.frameSinceNanos()).isZero();
    }

    @Test
    void aBlockOverTheBudgetIsSkippedWithAnErrorNamingTheLimitAndTheStreamGoesOn() throws Exception {
        BlockBudget budget = BlockBudget.of("limits.socketBlockBudgetBytes", 100_000);
        byte[] head = "{\"bytes\":300000}\n".getBytes(UTF_8);
        byte[] tail = "{\"op\":\"ping\"}\n".getBytes(UTF_8);
        byte[] wire = new byte[head.length + 300_000 + tail.length];
        System.arraycopy(head, 0, wire, 0, head.length);
        System.arraycopy(tail, 0, wire, head.length + 300_000, tail.length);
        FrameReader reader = new FrameReader(new TrickleInputStream(wire), 1_024, 1 << 20, budget);
        assertThatThrownBy(reader::read).isInstanceOfSatisfying(FrameException.class, e -> {
            assertThat(e.code()).isEqualTo("block_budget");
            assertThat(e.fatal()).isFalse();
            assertThat(e.getMessage()).contains("limits.socketBlockBudgetBytes=100000");
        });
        assertThat(budget.reserved()).isZero();
        assertThat(reader.read().header().path("op").asText()).isEqualTo("ping");
        assertThat(reader.read()).isNull();
    }

    @Test
    void aStreamThatEndsInsideABlockGivesItsReservationBack() throws Exception {
        BlockBudget budget = BlockBudget.of("limits.socketBlockBudgetBytes", 1 << 20);
        byte[] wire = ("{\"bytes\":100000}\n" + "x".repeat(70_000)).getBytes(UTF_8);
        FrameReader reader = new FrameReader(new ByteArrayInputStream(wire), 1_024, 1 << 20, budget);
        assertThatThrownBy(reader::read).isInstanceOfSatisfying(FrameException.class,
                e -> assertThat(e.code()).isEqualTo("truncated"));
        assertThat(budget.reserved()).isZero();
    }
}
