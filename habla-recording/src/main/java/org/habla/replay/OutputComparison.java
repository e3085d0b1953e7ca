package org.habla.replay;

import com.fasterxml.jackson.databind.node.JsonNodeFactory;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.zip.CRC32;
import org.habla.graph.GraphTap;
import org.habla.net.Frame;
import org.habla.net.SampleCodec;
import org.habla.sample.Payload;
import org.habla.sample.Sample;

/**
 * Collects what a replay produces — exposed outputs and the commands it would have sent — beside what the
 * recording holds, and compares them value by value in order. Values are compared in their wire form, so a
 * number read back from the file equals the number the method made. A tap: everything is handed on to
 * {@code next} (a recorder of the replay, or nothing).
 */
public final class OutputComparison implements GraphTap {

    static final String COMMANDS = "commands";

    private final GraphTap next;
    private final Map<String, List<String>> recorded = new LinkedHashMap<>();
    private final Map<String, List<String>> replayed = new LinkedHashMap<>();

    OutputComparison(GraphTap next) {
        this.next = next;
    }

    @Override
    public void skipped(String methodId, String input, long arrival) {
        next.skipped(methodId, input, arrival);
    }

    /** A value's wire form: its JSON fields, and a checksum of its binary block if it has one. */
    public static String canonical(Payload p) {
        Frame f = SampleCodec.withValue(JsonNodeFactory.instance.objectNode(), p);
        if (f.body().length == 0) {
            return f.header().toString();
        }
        CRC32 crc = new CRC32();
        crc.update(f.body());
        return f.header() + "#" + Long.toHexString(crc.getValue());
    }

    synchronized void expectOutput(String method, String output, Sample s) {
        recorded.computeIfAbsent(method + "." + output, k -> new ArrayList<>()).add(canonical(s.payload()));
    }

    synchronized void expectCommand(String iface, String channel, Sample s) {
        recorded.computeIfAbsent(COMMANDS, k -> new ArrayList<>()).add(iface + "." + channel + " " + canonical(s.payload()));
    }

    private synchronized void produced(String key, String value) {
        replayed.computeIfAbsent(key, k -> new ArrayList<>()).add(value);
    }

    /** Every stream seen on either side, outputs first (in the order met), then the commands. */
    synchronized List<StreamMatch> matches() {
        List<String> keys = new ArrayList<>(recorded.keySet());
        replayed.keySet().stream().filter(k -> !keys.contains(k)).forEach(keys::add);
        keys.remove(COMMANDS);
        keys.add(COMMANDS);
        List<StreamMatch> out = new ArrayList<>();
        for (String k : keys) {
            List<String> a = recorded.getOrDefault(k, List.of());
            List<String> b = replayed.getOrDefault(k, List.of());
            int same = 0;
            int first = -1;
            for (int i = 0; i < Math.max(a.size(), b.size()); i++) {
                if (i < a.size() && i < b.size() && a.get(i).equals(b.get(i))) {
                    same++;
                } else if (first < 0) {
                    first = i;
                }
            }
            out.add(new StreamMatch(k, a.size(), b.size(), same, first));
        }
        return out;
    }

    @Override
    public void reading(String interfaceId, String channel, Sample sample) {
        next.reading(interfaceId, channel, sample);
    }

    @Override
    public void command(String interfaceId, String channel, Sample sample, boolean sent) {
        if (sent) {
            produced(COMMANDS, interfaceId + "." + channel + " " + canonical(sample.payload()));
        }
        next.command(interfaceId, channel, sample, sent);
    }

    @Override
    public void control(String socket, String input, Sample sample) {
        next.control(socket, input, sample);
    }

    @Override
    public void periodic(String task, long micros, long handled) {
        next.periodic(task, micros, handled);
    }

    @Override
    public void writerLeft(String socket) {
        next.writerLeft(socket);
    }

    @Override
    public void link(String interfaceId, boolean up, long micros) {
        next.link(interfaceId, up, micros);
    }

    @Override
    public void output(String methodId, String output, Sample sample) {
        produced(methodId + "." + output, canonical(sample.payload()));
        next.output(methodId, output, sample);
    }
}
