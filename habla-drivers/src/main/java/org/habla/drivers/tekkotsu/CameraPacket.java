package org.habla.drivers.tekkotsu;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.util.ArrayList;
import java.util.List;

/**
 * One image packet of Tekkotsu's camera streams (raw camera, port 10011), as sent over TCP.
 * <pre>
 * "TekkotsuImage"   LoadSave string (0D 00 00 00, 13 chars, 00)
 * encoding          i32  0 = colour (Y, U, V sections), 1 = one channel
 * compression       i32  0 = none, 1 = JPEG (decide by each section's format, not by this)
 * width, height     u32  size of the largest channel
 * timestamp         u32  ms since boot
 * frame             u32  camera frame number
 * then 1 section (a JPEGColor section holds all three channels, encoding 1 has one), or 3 (Y, U, V):
 *   "FbkImage"      LoadSave string
 *   width, height   u32  this channel's size
 *   layer, channel  u32  resolution layer; 0 = Y, 1 = U, 2 = V
 *   format          LoadSave string: "RawImage" | "JPEGColor" | "JPEGGrayscale"
 *   payload         RawImage: width × height bytes; JPEG*: u32 length + the JPEG stream
 * </pre>
 * The header is 42 bytes; nothing gives the packet's length, so an unknown format cannot be skipped.
 */
record CameraPacket(int encoding, int compression, int width, int height, long timestampMs, long frame,
        List<Section> sections) {

    static final String MAGIC_TEXT = "TekkotsuImage";
    /** The magic as a LoadSave string, the only marker a lost TCP stream can be re-found by. */
    static final byte[] MAGIC = loadSave(MAGIC_TEXT);
    /** No Aibo camera layer is larger (416 × 320 at skip 0). */
    static final int MAX_SIDE = 2_048;
    static final int MAX_JPEG_BYTES = 4 << 20;
    private static final int MAX_NAME_CHARS = 64;

    /** One channel section of a packet. */
    record Section(int width, int height, int layer, int channel, String format, byte[] data) {
    }

    /** Reads the rest of a packet whose magic has been read already. */
    static CameraPacket readAfterMagic(WireInput in) throws IOException {
        int encoding = in.i32("camera encoding");
        int compression = in.i32("camera compression");
        int width = side(in, "camera width");
        int height = side(in, "camera height");
        long timestamp = in.u32("camera timestamp");
        long frame = in.u32("camera frame number");
        if (encoding != 0 && encoding != 1) {
            throw new WireInput.MalformedFieldException("camera encoding is " + encoding + ", not 0 (colour) or 1");
        }
        List<Section> sections = new ArrayList<>();
        sections.add(section(in));
        if (encoding == 0 && !sections.get(0).format().equals("JPEGColor")) {
            sections.add(section(in));
            sections.add(section(in));
        }
        return new CameraPacket(encoding, compression, width, height, timestamp, frame, List.copyOf(sections));
    }

    private static Section section(WireInput in) throws IOException {
        String creator = in.loadSaveString(MAX_NAME_CHARS, "camera section creator");
        if (!creator.equals("FbkImage")) {
            throw new WireInput.MalformedFieldException("camera section creator is '" + creator
                    + "', not 'FbkImage'");
        }
        int width = side(in, "section width");
        int height = side(in, "section height");
        int layer = in.i32("section layer");
        int channel = in.i32("section channel");
        String format = in.loadSaveString(MAX_NAME_CHARS, "section format");
        byte[] data = switch (format) {
            case "RawImage" -> in.bytes(width * height, "raw image pixels");
            case "JPEGColor", "JPEGGrayscale" -> {
                long length = in.u32("JPEG length");
                if (length > MAX_JPEG_BYTES) {
                    throw new WireInput.MalformedFieldException("JPEG length " + length + " is over the limit of "
                            + MAX_JPEG_BYTES + " bytes");
                }
                yield in.bytes((int) length, "JPEG data");
            }
            default -> throw new WireInput.MalformedFieldException("camera section format '" + format
                    + "' is not one the raw camera sends (RawImage, JPEGColor, JPEGGrayscale)");
        };
        return new Section(width, height, layer, channel, format, data);
    }

    private static int side(WireInput in, String field) throws IOException {
        long v = in.u32(field);
        if (v < 1 || v > MAX_SIDE) {
            throw new WireInput.MalformedFieldException(field + " is " + v + ", not in 1.." + MAX_SIDE);
        }
        return (int) v;
    }

    static byte[] loadSave(String text) {
        byte[] chars = text.getBytes(StandardCharsets.ISO_8859_1);
        byte[] out = new byte[chars.length + 5];
        out[0] = (byte) chars.length;
        out[1] = (byte) (chars.length >>> 8);
        out[2] = (byte) (chars.length >>> 16);
        out[3] = (byte) (chars.length >>> 24);
        System.arraycopy(chars, 0, out, 4, chars.length);
        return out;
    }
}
