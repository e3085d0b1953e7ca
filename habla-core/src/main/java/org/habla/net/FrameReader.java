package org.habla.net;

import com.fasterxml.jackson.core.JsonFactory;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.core.StreamReadFeature;
import com.fasterxml.jackson.core.util.JsonRecyclerPools;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.io.EOFException;
import java.io.IOException;
import java.io.InputStream;
import java.nio.ByteBuffer;
import java.nio.charset.CharacterCodingException;
import java.nio.charset.CodingErrorAction;
import java.nio.charset.StandardCharsets;
import java.util.Objects;

/**
 * Reads the frames of every HABLA socket (control side, interface protocol, workers): a chain of small
 * bounded stages, each with its own error code.
 *
 * <pre>
 *   one frame on the wire
 *   +------------------------------------------------+----+  +-----------------------------+
 *   | {"type":"sample", ... ,"bytes":N}  (UTF-8 JSON) | \n |  | N raw bytes (only if "bytes")|
 *   +------------------------------------------------+----+  +-----------------------------+
 *   |&lt;------------ at most maxLineBytes --------------&gt;|      |&lt;--- 0 &lt;= N &lt;= maxBinaryBytes -&gt;|
 *                       (a '\r' before '\n' is dropped)
 *
 *   InputStream
 *     -&gt; LineFramer     bounded line          line_too_long (skipped to the next '\n')
 *     -&gt; UTF-8 decoder  strict                bad_utf8
 *     -&gt; Jackson        one JSON value        bad_json, not_object
 *     -&gt; bytes trailer  N raw bytes           bad_bytes; binary_too_large (fatal); truncated (fatal);
 *                       memory reserved from   block_budget (the block is read and dropped)
 *                       a BlockBudget as the
 *                       bytes arrive
 *     -&gt; Frame(header, body)
 * </pre>
 *
 * A reader may be told to refuse blocks for a while ({@link #refuseBlocks}). Blank lines are skipped (a person typing into {@code nc} may press Enter twice). Recoverable errors
 * leave the stream at the next frame; after a fatal one the connection must be closed. Not thread-safe,
 * except {@link #frameSinceNanos()}, which a watchdog of slow frames reads.
 */
public final class FrameReader {

    /**
     * Jackson's buffers, shared by every connection. Its default keeps a set per thread for the thread's life:
     * with a reader and a writer thread per connection, that was about 40 KB held by every idle connection.
     */
    private static final int JSON_BUFFER_SETS = 64;

    /** Parses wire JSON strictly: no trailing tokens, no duplicate keys. */
    static final ObjectMapper JSON = JsonMapper.builder(JsonFactory.builder()
                    .recyclerPool(JsonRecyclerPools.newBoundedPool(JSON_BUFFER_SETS)).build())
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .enable(StreamReadFeature.STRICT_DUPLICATE_DETECTION)
            .enable(StreamReadFeature.USE_FAST_DOUBLE_PARSER) // the same doubles, parsed in a fraction of the time
            .build();

    private final LineFramer lines;
    private final int maxBinaryBytes;
    private final BlockBudget budget;
    /** What a header that declares a block gets while blocks are refused, or null while they are read. */
    private FrameException blockRefusal;

    /** A reader whose blocks take as much memory as they declare, up to {@code maxBinaryBytes} each. */
    public FrameReader(InputStream in, int maxLineBytes, int maxBinaryBytes) {
        this(in, maxLineBytes, maxBinaryBytes, BlockBudget.unbounded());
    }

    /** A reader whose blocks reserve their memory from {@code budget} as their bytes arrive. */
    public FrameReader(InputStream in, int maxLineBytes, int maxBinaryBytes, BlockBudget budget) {
        if (maxBinaryBytes < 0) {
            throw new IllegalArgumentException("maxBinaryBytes must not be negative, was " + maxBinaryBytes);
        }
        this.lines = new LineFramer(in, maxLineBytes);
        this.maxBinaryBytes = maxBinaryBytes;
        this.budget = Objects.requireNonNull(budget, "budget");
    }

    /**
     * Refuses blocks from now on: a header that declares {@code "bytes"} throws {@code refusal} (make it fatal: the
     * block that follows cannot be skipped) and nothing of the block is read. A port refuses them from a connection
     * that has not authenticated, so that it buffers nothing for it beyond one line.
     */
    public void refuseBlocks(FrameException refusal) {
        this.blockRefusal = java.util.Objects.requireNonNull(refusal, "refusal");
    }

    /** Reads blocks again, within {@code maxBinaryBytes} and the budget. */
    public void acceptBlocks() {
        this.blockRefusal = null;
    }

    /**
     * When the frame being read got its first byte ({@link System#nanoTime()}), or 0 while the reader waits
     * between frames. Safe to call from any thread.
     */
    public long frameSinceNanos() {
        return lines.frameSinceNanos();
    }

    /** The bytes of the stream taken by the frames read so far (and by what was skipped): where the next begins. */
    public long position() {
        return lines.position();
    }

    /**
     * Reads the next frame.
     *
     * @return the frame, or {@code null} at a clean end of stream
     * @throws FrameException for a frame that breaks the protocol ({@link FrameException#fatal()} says
     *                        whether the stream can go on)
     * @throws IOException    if the stream fails
     */
    public Frame read() throws IOException {
        try {
            return readFrame();
        } finally {
            lines.frameDone();
        }
    }

    private Frame readFrame() throws IOException {
        byte[] line;
        while (true) {
            line = lines.readLine();
            if (line == null) {
                return null;
            }
            if (!isBlank(line)) {
                break;
            }
            lines.frameDone();
        }
        ObjectNode header = ascii(line) ? parse(line) : parse(decode(line));
        JsonNode count = header.get("bytes");
        if (count == null) {
            return Frame.of(header);
        }
        if (blockRefusal != null) {
            throw blockRefusal;
        }
        if (!count.isIntegralNumber() || !count.canConvertToLong() || count.longValue() < 0) {
            throw FrameException.recoverable("bad_bytes", "\"bytes\" must be a whole number >= 0, was " + count);
        }
        if (count.longValue() > maxBinaryBytes) {
            throw FrameException.fatal("binary_too_large", "\"bytes\": " + count + " is over maxBinaryBytes="
                    + maxBinaryBytes + "; the stream cannot be resynchronised");
        }
        try {
            return new Frame(header, lines.readBytes(count.intValue(), budget));
        } catch (EOFException e) {
            throw FrameException.fatal("truncated", "the stream ended inside a binary block: " + e.getMessage());
        }
    }

    private static String decode(byte[] line) throws FrameException {
        try {
            return StandardCharsets.UTF_8.newDecoder()
                    .onMalformedInput(CodingErrorAction.REPORT)
                    .onUnmappableCharacter(CodingErrorAction.REPORT)
                    .decode(ByteBuffer.wrap(line))
                    .toString();
        } catch (CharacterCodingException e) {
            throw FrameException.recoverable("bad_utf8", "the line is not valid UTF-8");
        }
    }

    /** Whether every byte of {@code line} is ASCII, so that it is UTF-8 and Jackson may read the bytes as they are. */
    private static boolean ascii(byte[] line) {
        for (byte b : line) {
            if (b < 0) {
                return false;
            }
        }
        return true;
    }

    private static ObjectNode parse(byte[] asciiLine) throws FrameException {
        JsonNode node;
        try {
            node = JSON.readTree(asciiLine);
        } catch (JsonProcessingException e) {
            throw FrameException.recoverable("bad_json", "the line is not JSON: " + e.getOriginalMessage());
        } catch (IOException e) {
            throw new java.io.UncheckedIOException("reading JSON from memory", e); // a byte array does not fail
        }
        return object(node);
    }

    private static ObjectNode parse(String text) throws FrameException {
        JsonNode node;
        try {
            node = JSON.readTree(text);
        } catch (JsonProcessingException e) {
            throw FrameException.recoverable("bad_json", "the line is not JSON: " + e.getOriginalMessage());
        }
        return object(node);
    }

    private static ObjectNode object(JsonNode node) throws FrameException {
        if (node instanceof ObjectNode object) {
            return object;
        }
        throw FrameException.recoverable("not_object", "a frame must be a JSON object, was "
                + (node == null ? "nothing" : node.getNodeType().name().toLowerCase(java.util.Locale.ROOT)));
    }

    private static boolean isBlank(byte[] line) {
        for (byte b : line) {
            if (b != ' ' && b != '\t' && b != '\r') {
                return false;
            }
        }
        return true;
    }
}
