package org.habla.method;

/** Where a method is in the life cycle the engine runs: NEW → ATTACHED → RUNNING → STOPPED, or FAILED. */
public enum MethodState {
    NEW,
    ATTACHED,
    RUNNING,
    STOPPED,
    FAILED
}
