package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A method's bound params record as JSON and back, for a method placed on a worker: the daemon sends the
 * params it checked, and the worker binds them to the same record with the same strict rules, so both sides
 * run the method with exactly the same settings.
 */
public final class ParamsJson {

    private ParamsJson() {
    }

    /** The params record as the JSON object a config would hold. */
    public static ObjectNode write(Record params) {
        return ParamsBinder.STRICT.valueToTree(params);
    }

    /**
     * Binds {@code params} to {@code type} as the config loader does.
     *
     * @throws ConfigException naming every wrong parameter, at paths under {@code $.params}
     */
    public static Record read(JsonNode params, Class<? extends Record> type) throws ConfigException {
        ConfigErrors errors = new ConfigErrors();
        java.util.Optional<Record> bound = ParamsBinder.bind(params, type, JsonPath.ROOT.field("params"), errors);
        if (bound.isEmpty()) {
            throw new ConfigException(errors.sorted());
        }
        return bound.get();
    }
}
