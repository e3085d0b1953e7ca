package org.habla.config;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A params record as JSON and back. For a method placed on a worker: the daemon sends the params it checked, and
 * the worker binds them to the same record with the same strict rules, so both sides run the method with exactly
 * the same settings. For Java code that needs a params record (a test, a type made inside another): it is bound
 * from JSON as a config's would be, so it receives the declared defaults and passes the declared ranges.
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

    /**
     * The params record with every parameter at its declared default, bound from {@code {}}.
     *
     * @throws IllegalArgumentException when {@code type} has a required parameter
     */
    public static <P extends Record> P defaults(Class<P> type) {
        return of(type, "{}");
    }

    /**
     * The params record bound from JSON text, as a config's {@code params} would be: {@code of(Params.class,
     * "{\"spreadM\": 0.2}")}.
     *
     * @throws IllegalArgumentException naming every wrong parameter, at paths under {@code $.params}
     */
    public static <P extends Record> P of(Class<P> type, String json) {
        try {
            return type.cast(read(ParamsBinder.STRICT.readTree(json), type));
        } catch (ConfigException e) {
            throw new IllegalArgumentException(e.getMessage(), e);
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalArgumentException("params are not JSON: " + e.getOriginalMessage(), e);
        }
    }
}
