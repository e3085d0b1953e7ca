package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.assertThatCode;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.node.ObjectNode;
import java.lang.reflect.ParameterizedType;
import java.lang.reflect.RecordComponent;
import java.lang.reflect.Type;
import java.util.ArrayList;
import java.util.LinkedHashSet;
import java.util.List;
import java.util.Map;
import java.util.Optional;
import java.util.Set;
import java.util.stream.Stream;
import org.habla.plugin.Param;
import org.habla.plugin.ParamDefaults;
import org.habla.plugin.ParamRange;
import org.habla.plugin.PluginRegistry;
import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.Arguments;
import org.junit.jupiter.params.provider.MethodSource;

/**
 * Each default is written once, in its parameter's {@link Param#defaultValue()}: for every discovered
 * method, driver and bridge type (and every record inside their params), the default is JSON of the
 * parameter's type and inside the range the parameter declares, and a config that leaves the key out gets
 * exactly that value when the record is bound.
 */
class ParamDefaultsTest {

    /** The required keys of types that have some, so a minimal params object binds. */
    private static final Map<String, String> REQUIRED = Map.of(
            "method occupancy", "{\"zones\": [\"desk\"]}",
            "method light-levels", "{\"zones\": [\"desk\"]}",
            "method room-action", "{\"speaker\": true}",
            "driver habla", "{\"channels\": [{\"name\": \"ir\", \"direction\": \"reading\", \"kind\": \"number\"}]}",
            "driver mqtt", "{\"readings\": [{\"channel\": \"t\", \"topic\": \"room/t\"}]}",
            "bridge mqtt", "{\"publish\": [\"t\"]}");

    private static final PluginRegistry REGISTRY = PluginRegistry.discover();

    static Stream<Arguments> paramsTypes() {
        List<Arguments> types = new ArrayList<>();
        REGISTRY.methods().forEach((name, p) -> types.add(Arguments.of("method " + name, p.paramsType())));
        REGISTRY.drivers().forEach((name, p) -> types.add(Arguments.of("driver " + name, p.paramsType())));
        REGISTRY.bridges().forEach((name, p) -> types.add(Arguments.of("bridge " + name, p.paramsType())));
        return types.stream();
    }

    /** Every params record and every record reachable from one through its components. */
    static Stream<Class<?>> everyRecord() {
        Set<Class<?>> found = new LinkedHashSet<>();
        paramsTypes().forEach(a -> collect((Class<?>) a.get()[1], found));
        return found.stream();
    }

    @Test
    void everyDiscoveredTypeIsChecked() {
        assertThat(paramsTypes()).hasSizeGreaterThan(40);
        assertThat(everyRecord().count()).isGreaterThan(paramsTypes().count());
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("everyRecord")
    void everyDefaultIsJsonOfItsParametersType(Class<?> record) {
        for (RecordComponent c : record.getRecordComponents()) {
            Param doc = c.getAnnotation(Param.class);
            if (doc == null || doc.defaultValue().isEmpty()) {
                continue;
            }
            String what = record.getName() + "." + c.getName() + " = " + doc.defaultValue();
            assertThat(doc.defaultNote()).as(what + " has both a default and a note").isEmpty();
            JsonNode d = ParamDefaults.json(record, c).orElseThrow();
            assertThatCode(() -> ParamsBinder.STRICT.convertValue(d, ParamsBinder.STRICT.constructType(c.getGenericType())))
                    .as(what + " is not a " + c.getGenericType().getTypeName())
                    .doesNotThrowAnyException();
        }
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("paramsTypes")
    void aMinimalParamsObjectBindsToEveryDeclaredDefault(String type, Class<? extends Record> params) throws Exception {
        Record bound = bindMinimal(type, params);
        Set<String> given = new LinkedHashSet<>();
        minimal(type).fieldNames().forEachRemaining(given::add);
        assertDefaultsIn(bound, params, given, type + " bound from " + minimal(type));
    }

    @ParameterizedTest(name = "{0}")
    @MethodSource("everyRecord")
    void everyDeclaredDefaultIsInsideItsDeclaredRange(Class<?> record) {
        for (RecordComponent c : record.getRecordComponents()) {
            Param doc = c.getAnnotation(Param.class);
            Optional<JsonNode> d = ParamDefaults.json(record, c);
            Optional<ParamRange> range = ParamRange.of(doc);
            if (d.isEmpty() || range.isEmpty()) {
                continue;
            }
            List<JsonNode> numbers = new ArrayList<>();
            if (d.get().isNumber()) {
                numbers.add(d.get());
            } else {
                d.get().elements().forEachRemaining(numbers::add);
            }
            for (JsonNode n : numbers) {
                assertThat(range.get().refusal(n.doubleValue(), n.asText()))
                        .as("%s.%s = %s, %s", record.getName(), c.getName(), n, range.get()).isNull();
            }
        }
    }

    /**
     * Each component with a declared default that was not {@code given} holds exactly that default,
     * compared as JSON; records inside (a list of channel specs) are checked the same way.
     */
    private static void assertDefaultsIn(Record bound, Class<?> type, Set<String> given, String what) throws Exception {
        for (RecordComponent c : type.getRecordComponents()) {
            Optional<JsonNode> d = ParamDefaults.json(type, c);
            if (d.isEmpty() || given.contains(ParamsBinder.jsonName(c))) {
                Object value = c.getAccessor().invoke(bound);
                for (Object inner : value instanceof java.util.Collection<?> list ? list : java.util.Collections.singletonList(value)) {
                    if (inner instanceof Record r) {
                        assertDefaultsIn(r, r.getClass(), Set.of(), what + " " + c.getName());
                    }
                }
                continue;
            }
            Object expected = ParamsBinder.STRICT.convertValue(d.get(), ParamsBinder.STRICT.constructType(c.getGenericType()));
            Object actual = c.getAccessor().invoke(bound);
            JsonNode actualJson = ParamsBinder.STRICT.valueToTree(actual);
            assertThat(actualJson)
                    .as("%s: %s (declared %s)", what, c.getName(), d.get())
                    .isEqualTo(ParamsBinder.STRICT.valueToTree(expected));
        }
    }

    private static Record bindMinimal(String type, Class<? extends Record> params) throws Exception {
        ConfigErrors errors = new ConfigErrors();
        Optional<Record> bound = ParamsBinder.bind(minimal(type), params, JsonPath.ROOT.field("params"), errors);
        assertThat(errors.sorted()).as(type + ": add its required keys to REQUIRED").isEmpty();
        return bound.orElseThrow();
    }

    private static ObjectNode minimal(String type) {
        try {
            return (ObjectNode) ParamsBinder.STRICT.readTree(REQUIRED.getOrDefault(type, "{}"));
        } catch (com.fasterxml.jackson.core.JsonProcessingException e) {
            throw new IllegalStateException(e);
        }
    }

    private static void collect(Type t, Set<Class<?>> found) {
        if (t instanceof ParameterizedType p) {
            for (Type arg : p.getActualTypeArguments()) {
                collect(arg, found);
            }
        } else if (t instanceof Class<?> c && c.isArray()) {
            collect(c.getComponentType(), found);
        } else if (t instanceof Class<?> c && c.isRecord() && found.add(c)) {
            for (RecordComponent component : c.getRecordComponents()) {
                collect(component.getGenericType(), found);
            }
        }
    }
}
