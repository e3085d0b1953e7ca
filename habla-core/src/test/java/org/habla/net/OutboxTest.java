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
}
