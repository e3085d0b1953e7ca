package org.habla.monitor;

/**
 * Whether, and to where, a Foxglove client may publish (the protocol's {@code clientPublish}: a client
 * advertises a channel and sends messages on it). Off in HABLA: a client that publishes could drive the robot,
 * so it waits for authentication and the command role. The implementation that allows it decides per client
 * and hands each message to the socket it names, as a control client's write.
 */
public interface FoxglovePublishing {

    /** Whether clients of this server may advertise channels and publish on them. */
    boolean allowed();

    /** A message a client published on {@code topic} (JSON text); called only when {@link #allowed()}. */
    void publish(String topic, String message);

    /** No client publishes: the server does not announce {@code clientPublish} and refuses an advertise. */
    FoxglovePublishing OFF = new FoxglovePublishing() {
        @Override
        public boolean allowed() {
            return false;
        }

        @Override
        public void publish(String topic, String message) {
            throw new IllegalStateException("client publishing is off");
        }
    };
}
