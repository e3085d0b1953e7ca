package org.habla.sample;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A typed value that travels between methods as a record: a range scan, a camera model, a head pose. Inside the
 * daemon a {@link RecordValue} made with {@link RecordValue#of(RecordForm)} carries the Java object itself, so the
 * method that reads it takes it back with {@link RecordValue#form(Class)} without any JSON; the JSON form is made
 * once, and only when the value crosses an edge (a control socket, a recording, a worker link, the monitor).
 *
 * <p>An implementation is immutable, and its {@link #toJson()} has exactly the fields of the record its
 * {@link org.habla.sample.RecordForm.Fields} annotation names (a test of the method library checks it).
 */
public interface RecordForm {

    /** The record as JSON: a new object each call, the caller may keep it. */
    ObjectNode toJson();

    /** The JSON field names of a record form, in order; an optional field is marked by a trailing {@code ?}. */
    @java.lang.annotation.Retention(java.lang.annotation.RetentionPolicy.RUNTIME)
    @java.lang.annotation.Target(java.lang.annotation.ElementType.TYPE)
    @interface Fields {
        String[] value();
    }
}
