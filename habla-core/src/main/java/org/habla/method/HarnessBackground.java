package org.habla.method;

import java.util.ArrayDeque;
import java.util.concurrent.Callable;
import java.util.function.Consumer;

/**
 * The background work a method under {@link MethodHarness} asks for: held until the test runs it, or run at once
 * once the test says so. A task that throws fails the method, as the engine's pool does; its result comes back as
 * an ordinary turn.
 */
final class HarnessBackground {

    private final ArrayDeque<Runnable> pending = new ArrayDeque<>();
    private boolean atOnce;

    <T> void submit(MethodLifecycle lifecycle, String what, Callable<T> task, Consumer<T> done) {
        Runnable r = () -> {
            T result;
            try {
                result = task.call();
            } catch (Exception e) {
                lifecycle.fail(what, e);
                return;
            }
            lifecycle.runTurn(what + " (done)", () -> done.accept(result));
        };
        if (atOnce) {
            r.run();
        } else {
            pending.add(r);
        }
    }

    /** Runs what is held, and from now on every task as soon as it is asked for. */
    void runAtOnceFromNowOn() {
        atOnce = true;
        runAll();
    }

    /** Runs what is held so far; returns how many tasks ran. */
    int runAll() {
        int n = 0;
        while (!pending.isEmpty()) {
            pending.poll().run();
            n++;
        }
        return n;
    }
}
