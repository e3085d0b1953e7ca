package org.habla.sample;

import com.fasterxml.jackson.databind.node.ObjectNode;

/**
 * A typed value that travels between methods as a record: a range scan, a camera model, the nearest obstacle.
 * Inside the daemon a {@link RecordValue} made with {@link RecordValue#of(RecordForm)} carries the Java object
 * itself, so the method that reads it takes it back with {@link RecordValue#form(Class)} without any JSON, and
 * the record's accessors ({@link RecordValue#number}, {@link RecordValue#get}) read its fields through its
 * {@link #layout()}; the JSON form is made only when the value crosses an edge (a control socket, a recording,
 * a worker link, the monitor, a bridge).
 *
 * <p>An implementation is immutable, its {@code equals} is value equality (two forms whose JSON is equal are
 * equal), and its JSON has exactly the fields its layout declares, in that order.
 */
public interface RecordForm {

    /** The fields of this form's records, declared once for the type: names, units, meanings and frames. */
    RecordLayout<?> layout();

    /** The record as JSON, written from the {@link #layout()}: a new object each call, the caller may keep it. */
    default ObjectNode toJson() {
        return layout().json(this);
    }
}
