package org.habla.plugin;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Documents one parameter of a params record: its unit, its default and its meaning. Read by
 * {@code habla plugins}, the docs and the config schema, and by the config loader, which fills a
 * parameter left out of {@code params} with its {@link #defaultValue()} before the record is built.
 *
 * <p>A parameter is required when it has neither a {@link #defaultValue()} nor a {@link #defaultNote()}.
 *
 * <p>A number parameter may declare its range ({@link #min()}, {@link #max()}, {@link #greaterThan()}); the config
 * loader checks it, for the value or for every number of a list or map, and names the JSON path of a value outside
 * it. A rule that relates two parameters ({@code nearM} below {@code farM}) stays in the record's constructor.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.RECORD_COMPONENT, ElementType.FIELD, ElementType.PARAMETER, ElementType.METHOD})
public @interface Param {

    /** One sentence: what the parameter means. */
    String value();

    /** The unit ({@code "m"}, {@code "ms"}, {@code "rad"}), empty if none. */
    String unit() default "";

    /**
     * The default as JSON text of the parameter's type ({@code "0.5"}, {@code "\"jpeg\""},
     * {@code "[]"}), filled in when the key is left out; empty when there is no fixed default.
     */
    String defaultValue() default "";

    /**
     * What happens when the key is left out and there is no fixed default, in words ({@code "channel
     * metadata, else 0.18"}): the record receives null and decides. Empty for a parameter with a
     * {@link #defaultValue()} or a required one.
     */
    String defaultNote() default "";

    /**
     * The value is a file path. A relative path is taken from the folder of the config file that
     * names it, so a config and the files beside it move together.
     */
    boolean file() default false;

    /** The least value allowed, inclusive; none when left at minus infinity. */
    double min() default Double.NEGATIVE_INFINITY;

    /** The greatest value allowed, inclusive; none when left at plus infinity. */
    double max() default Double.POSITIVE_INFINITY;

    /** The value must be greater than this ({@code greaterThan = 0}: a positive number); none at minus infinity. */
    double greaterThan() default Double.NEGATIVE_INFINITY;
}
