package org.habla.methods.speech;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashMap;
import java.util.Iterator;
import java.util.List;
import java.util.Map;

/**
 * Moonshine's tokenizer: byte-pair encoding over the vocabulary and merges of its {@code tokenizer.json}
 * (a SentencePiece-style BPE: a space is written {@code ▁} and the text starts with one; a character the
 * vocabulary lacks is spelt as its UTF-8 bytes, tokens {@code <0x00>} to {@code <0xFF>}).
 *
 * <p>Encoding starts from single characters and merges, again and again, the adjacent pair whose merge
 * comes first in the file's list, until no listed merge applies: the tokens the model was trained on for
 * that text. Only encoding is needed to score a grammar's phrases; {@link #decode} is there to read what
 * the model would say.
 */
public final class MoonshineTokenizer {

    /** The token that starts every decoding. */
    public static final int START = 1;
    /** The token that ends a transcription. */
    public static final int END = 2;
    static final String SPACE = "\u2581";

    private final Map<String, Integer> vocab;
    private final String[] pieces;
    private final Map<String, Integer> mergeRank;

    private MoonshineTokenizer(Map<String, Integer> vocab, Map<String, Integer> mergeRank) {
        this.vocab = vocab;
        this.mergeRank = mergeRank;
        int max = vocab.values().stream().mapToInt(Integer::intValue).max().orElse(0);
        this.pieces = new String[max + 1];
        vocab.forEach((piece, id) -> pieces[id] = piece);
    }

    /** Reads {@code tokenizer.json}; an IOException names the file and what is wrong with it. */
    public static MoonshineTokenizer load(Path tokenizerJson) throws IOException {
        JsonNode model = new ObjectMapper().readTree(tokenizerJson.toFile()).path("model");
        if (!"BPE".equals(model.path("type").asText()) || !model.path("vocab").isObject()
                || !model.path("merges").isArray()) {
            throw new IOException(tokenizerJson + " is not a BPE tokenizer (model.type BPE, model.vocab, model.merges)");
        }
        Map<String, Integer> vocab = new HashMap<>();
        for (Iterator<Map.Entry<String, JsonNode>> it = model.path("vocab").fields(); it.hasNext(); ) {
            Map.Entry<String, JsonNode> e = it.next();
            vocab.put(e.getKey(), e.getValue().asInt());
        }
        Map<String, Integer> ranks = new HashMap<>();
        int rank = 0;
        for (JsonNode m : model.path("merges")) {
            String pair = m.isArray() ? m.get(0).asText() + " " + m.get(1).asText() : m.asText();
            ranks.putIfAbsent(pair, rank++);
        }
        return new MoonshineTokenizer(vocab, ranks);
    }

    /** The token of one vocabulary piece ({@code ▁} for a space before it), or -1 if the vocabulary lacks it. */
    public int piece(String piece) {
        return vocab.getOrDefault(piece, -1);
    }

    /** The tokens of {@code text}, without the start and end tokens. */
    public int[] encode(String text) {
        String normal = SPACE + text.replace(" ", SPACE);
        List<String> symbols = new ArrayList<>();
        normal.codePoints().forEach(cp -> symbols.add(new String(Character.toChars(cp))));
        while (symbols.size() > 1) {
            int best = -1;
            int bestRank = Integer.MAX_VALUE;
            for (int i = 0; i + 1 < symbols.size(); i++) {
                Integer r = mergeRank.get(symbols.get(i) + " " + symbols.get(i + 1));
                if (r != null && r < bestRank) {
                    bestRank = r;
                    best = i;
                }
            }
            if (best < 0) {
                break;
            }
            symbols.set(best, symbols.get(best) + symbols.remove(best + 1));
        }
        List<Integer> ids = new ArrayList<>();
        for (String s : symbols) {
            Integer id = vocab.get(s);
            if (id != null) {
                ids.add(id);
                continue;
            }
            for (byte b : s.getBytes(StandardCharsets.UTF_8)) {
                ids.add(vocab.getOrDefault(String.format("<0x%02X>", b & 0xff), 0));
            }
        }
        return ids.stream().mapToInt(Integer::intValue).toArray();
    }

    /** The text of these tokens (byte tokens joined back into characters, start and end tokens left out). */
    public String decode(int[] ids) {
        java.io.ByteArrayOutputStream bytes = new java.io.ByteArrayOutputStream();
        for (int id : ids) {
            if (id == START || id == END || id < 0 || id >= pieces.length || pieces[id] == null) {
                continue;
            }
            String p = pieces[id];
            if (p.length() == 6 && p.startsWith("<0x") && p.endsWith(">")) {
                bytes.write(Integer.parseInt(p.substring(3, 5), 16));
            } else {
                bytes.writeBytes(p.replace(SPACE, " ").getBytes(StandardCharsets.UTF_8));
            }
        }
        String text = bytes.toString(StandardCharsets.UTF_8);
        return text.startsWith(" ") ? text.substring(1) : text;
    }
}
