package org.habla.sample;

/**
 * The value a sample carries. Every payload is immutable: arrays handed in are copied,
 * arrays handed out are copies, so a payload can be shared by every subscriber of an output.
 */
public sealed interface Payload permits NumberValue, VectorValue, TextValue, RecordValue, AudioChunk, ImageFrame {

    PayloadKind kind();
}
