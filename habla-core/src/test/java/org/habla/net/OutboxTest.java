package org.habla.net;

import static org.assertj.core.api.Assertions.assertThat;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.List;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.Timeout;

@Timeout(10)
class OutboxTest {

    private static EncodedFrame sample(long seq) {
        return EncodedFrame.of(Frame.of(JsonNodeFactory.instance.objectNode().put("type", "sample").put("seq", seq)));
    }

    @Test
    void outboxesOfferedOneEncodedSampleHandTheSameBytesToTheirWriters() throws Exception {
        EncodedFrame once = sample(1);
        Outbox first = new Outbox(4, 4);
        Outbox second = new Outbox(4, 4);
        first.offerSample("out", once);
        second.offerSample("out", once);
        assertThat(first.take().getFirst().line()).isSameAs(second.take().getFirst().line()).isSameAs(once.line());
    }

    @Test
    void aFullOutboxDropsItsOldestSampleAndTellsTheCountBeforeTheNextSample() throws Exception {
        Outbox outbox = new Outbox(2, 4);
        assertThat(outbox.offerSample("out", sample(1))).isFalse();
        assertThat(outbox.offerSample("out", sample(2))).isFalse();
        assertThat(outbox.offerSample("out", sample(3))).isTrue();
        List<EncodedFrame> batch = outbox.take();
        assertThat(batch).extracting(EncodedFrame::type).containsExactly("dropped", "sample", "sample");
        assertThat(batch.get(0).frame().header().path("count").asLong()).isEqualTo(1);
        assertThat(batch.get(1).frame().header().path("seq").asLong()).isEqualTo(2);
        assertThat(outbox.droppedTotal()).isEqualTo(1);
    }

    @Test
    void aNewerNoticeReplacesAnUnsentOneOfTheSameType() throws Exception {
        Outbox outbox = new Outbox(2, 4);
        outbox.offerNotice(EncodedFrame.of(Frame.of(JsonNodeFactory.instance.objectNode().put("type", "stale")
                .put("stale", true))));
        outbox.offerNotice(EncodedFrame.of(Frame.of(JsonNodeFactory.instance.objectNode().put("type", "stale")
                .put("stale", false))));
        List<EncodedFrame> batch = outbox.take();
        assertThat(batch).hasSize(1);
        assertThat(batch.getFirst().frame().header().path("stale").asBoolean(true)).isFalse();
    }

    @Test
    void aSampleMayBeWrittenDirectlyOnlyWhileNothingWaitsAndNobodyWrites() throws Exception {
        Outbox outbox = new Outbox(4, 4);
        assertThat(outbox.claimDirect()).isTrue();
        assertThat(outbox.claimDirect()).as("a second sender while the first writes").isFalse();
        outbox.releaseDirect(null, false);

        outbox.offerSample("out", sample(1));
        assertThat(outbox.claimDirect()).as("a sample waits in the queue").isFalse();
        List<EncodedFrame> batch = outbox.take();
        assertThat(batch).hasSize(1);
        assertThat(outbox.claimDirect()).as("the writer is still writing its batch").isFalse();
        outbox.sent();
        assertThat(outbox.claimDirect()).isTrue();
        outbox.releaseDirect(null, false);

        outbox.rate(10);
        assertThat(outbox.claimDirect()).as("a rate limit decides when samples go").isFalse();
    }

    @Test
    void theEndOfALineBegunDirectlyGoesFirstAndIsNeitherDroppedNorReplaced() throws Exception {
        Outbox outbox = new Outbox(1, 4);
        EncodedFrame line = sample(1);
        assertThat(outbox.claimDirect()).isTrue();
        outbox.offerSample("out", sample(2)); // arrives while the direct sender writes
        EncodedFrame rest = new EncodedFrame(line.frame(), java.util.Arrays.copyOfRange(line.line(), 5, line.line().length));
        outbox.releaseDirect(rest, false);
        outbox.offerSample("out", sample(3)); // the queue holds one sample: 2 is dropped, the rest stays
        List<EncodedFrame> batch = outbox.take();
        assertThat(batch.getFirst()).isSameAs(rest);
        assertThat(batch).extracting(EncodedFrame::type).containsExactly("sample", "dropped", "sample");
        assertThat(batch.get(2).frame().header().path("seq").asLong()).isEqualTo(3);
    }

    @Test
    void anEvictionLineFollowsTheEndOfALineBegunAndWaitsForTheDirectSender() throws Exception {
        Outbox outbox = new Outbox(4, 4);
        EncodedFrame line = sample(1);
        assertThat(outbox.claimDirect()).isTrue();
        EncodedFrame error = EncodedFrame.of(Frame.of(JsonNodeFactory.instance.objectNode().put("type", "error")));
        outbox.finishWith(error);
        List<List<EncodedFrame>> taken = new java.util.concurrent.CopyOnWriteArrayList<>();
        Thread writer = Thread.ofVirtual().start(() -> {
            try {
                taken.add(outbox.take());
            } catch (InterruptedException e) {
                Thread.currentThread().interrupt();
            }
        });
        EncodedFrame rest = new EncodedFrame(line.frame(), java.util.Arrays.copyOfRange(line.line(), 3, line.line().length));
        outbox.releaseDirect(rest, false);
        writer.join();
        assertThat(taken.getFirst()).containsExactly(rest, error);
    }

    @Test
    void aSampleTheSocketTookNothingOfIsQueuedFirstAndMayBeDroppedLikeAnyOther() throws Exception {
        Outbox outbox = new Outbox(4, 4);
        EncodedFrame whole = sample(1);
        assertThat(outbox.claimDirect()).isTrue();
        outbox.releaseDirect(whole, true);
        assertThat(outbox.claimDirect()).isFalse();
        outbox.offerSample("out", sample(2));
        assertThat(outbox.take()).extracting(f -> f.frame().header().path("seq").asLong()).containsExactly(1L, 2L);
    }
}
