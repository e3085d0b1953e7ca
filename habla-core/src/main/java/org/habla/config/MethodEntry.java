package org.habla.config;

import java.util.Map;
import java.util.Optional;
import java.util.Set;
import org.habla.method.Layer;
import org.habla.method.Ports;
import org.habla.net.Expose;

/**
 * One element of the config's {@code methods} array as far as it could be read. A null component
 * means that part was missing or wrong, and the error is already recorded; the cross checks skip it.
 *
 * @param path     where the entry is ({@code $.methods[3]})
 * @param id       the id, or null
 * @param type     the method type, or null when unknown
 * @param layer    the layer, or null
 * @param inputKeys every key of the {@code inputs} object, read or not (so a bad source is not also "unwired")
 * @param inputs   input name → source, for the entries that parsed
 * @param commands output name → command channel, for the entries that parsed
 * @param params   the bound params record, or null
 * @param exposeGiven whether the entry has an {@code expose} key, readable or not
 * @param expose   the socket, if the entry has a readable one
 * @param host     the worker {@code host:port}, if given and readable
 * @param fallback what to do while the worker is lost
 * @param ports    the ports its type lists for these params, or null
 * @param feedback the inputs declared to close a wiring cycle, each with the path of its declaration
 * @param thread   the thread the config asks for
 */
record MethodEntry(JsonPath path, String id, String type, Layer layer, Set<String> inputKeys,
        Map<String, Source> inputs, Map<String, ChannelRef> commands, Record params, boolean exposeGiven,
        Optional<Expose> expose, Optional<String> host, Fallback fallback, Ports ports,
        Map<String, JsonPath> feedback, ThreadChoice thread) {

    /** Whether every part was read, so the entry can become a {@link MethodConfig}. */
    boolean complete() {
        return id != null && type != null && layer != null && params != null && ports != null;
    }

    MethodConfig toConfig() {
        return new MethodConfig(id, type, layer, inputs, commands, params, expose, host, fallback, feedback.keySet(),
                thread);
    }
}
