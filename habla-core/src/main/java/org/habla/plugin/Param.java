package org.habla.plugin;

import java.lang.annotation.ElementType;
import java.lang.annotation.Retention;
import java.lang.annotation.RetentionPolicy;
import java.lang.annotation.Target;

/**
 * Documents one parameter of a params record: its unit, its default (as JSON text, or empty when
 * the parameter is required) and its meaning. Read by {@code habla plugins}, the docs and the
 * config schema.
 */
@Retention(RetentionPolicy.RUNTIME)
@Target({ElementType.RECORD_COMPONENT, ElementType.FIELD, ElementType.PARAMETER, ElementType.METHOD})
public @interface Param {

    /** One sentence: what the parameter means. */
    String value();

    /** The unit ({@code "m"}, {@code "ms"}, {@code "rad"}), empty if none. */
    String unit() default "";

    /** The default as JSON text ({@code "0.5"}, {@code "\"jpeg\""}); empty means required. */
    String defaultValue() default "";

    /**
     * The value is a file path. A relative path is taken from the folder of the config file that
     * names it, so a config and the files beside it move together.
     */
    boolean file() default false;
}
