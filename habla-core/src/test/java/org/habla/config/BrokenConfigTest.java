package org.habla.config;

import static org.assertj.core.api.Assertions.assertThat;
import static org.assertj.core.api.Assertions.catchThrowableOfType;

import java.net.URISyntaxException;
import java.nio.file.Path;
import java.util.List;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

/**
 * Every file under {@code configs/broken/} holds exactly one fault; the loader must report exactly one
 * error, at the exact JSON path, with the key part of the message.
 */
class BrokenConfigTest {

    private final ConfigLoader loader = new ConfigLoader(TestPlugins.registry());

    @ParameterizedTest(name = "{0} is rejected at {1}")
    @CsvSource(delimiter = '|', textBlock = """
        syntax-error                      | $                               | invalid JSON at line 2, column 17
        duplicate-key                     | $                               | Duplicate field 'system'
        root-is-array                     | $                               | must be an object, not an array
        unknown-root-key                  | $.methds                        | unknown key 'methds' (allowed: $schema, bridges, description, interfaces, limits, methods, safety, security, status, system)
        socket-beyond-loopback-without-auth | $.methods[0].expose.bind      | socket 'action' binds 0.0.0.0, beyond loopback, without authentication
        status-beyond-loopback-without-auth | $.status.bind                 | the status endpoint binds 0.0.0.0, beyond loopback, without authentication
        monitor-beyond-loopback           | $.status.monitorBind            | the monitor has no authentication, so it may not listen on 0.0.0.0
        tls-socket-without-certificate    | $.methods[0].expose.tls         | a TLS socket needs security.tls with a certificate and its key
        credentials-file-missing          | $.security.credentials          | no-such.credentials.json $: no such file
        security-loopback-unknown         | $.security.loopback             | must be "open" or "authenticated", was "closed"
        missing-system                    | $.system                        | required key 'system' is missing
        system-not-a-string               | $.system                        | must be a string, not a number (5)
        limit-not-an-integer              | $.limits.maxLineBytes           | must be an integer in 1..16777216, not a string ("64k")
        limit-zero                        | $.limits.maxClientsPerPort      | must be in 1..1024, was 0
        limit-socket-budget-below-largest-block | $.limits.socketBlockBudgetBytes | must not be less than maxBinaryBytes (33554432)
        safety-unknown-key                | $.safety.watchdog               | unknown key 'watchdog' (allowed: watchdogMs)
        status-port-out-of-range          | $.status.port                   | must be in 0..65535, was 70000
        interfaces-not-an-array           | $.interfaces                    | must be an array, not an object
        unknown-driver                    | $.interfaces[0].driver          | unknown driver type 'arcos' (known: robot-sim)
        unknown-bridge-type               | $.bridges[0].type               | unknown bridge type 'carrier-pigeon' (known: none registered)
        bad-address                       | $.interfaces[0].address         | '127.0.0.1:port' is not an address
        reconnect-max-below-initial       | $.interfaces[0].reconnect.maxMs | must not be less than initialMs (500), was 100
        reconnect-keepalive-count-zero    | $.interfaces[0].reconnect.tcpKeepAliveCount | must be in 1..100, was 0
        bad-interface-id                  | $.interfaces[0].id              | '1robot' is not an id: a letter then
        duplicate-interface-id            | $.interfaces[1].id              | duplicate interface id 'robot': already used at $.interfaces[0].id
        duplicate-method-id               | $.methods[1].id                 | duplicate method id 'sonar': already used at $.methods[0].id
        duplicate-expose-port             | $.methods[3].expose.port        | duplicate port 7004: already used at $.methods[2].expose.port
        expose-port-is-status-port        | $.methods[0].expose.port        | duplicate port 7099: already used at $.status.port (the status endpoint's default)
        monitor-port-is-status-port       | $.status.monitorPort            | duplicate port 7099: already used at $.status.port
        duplicate-expose-name             | $.methods[1].expose.name        | duplicate socket name 'action': already used at $.methods[0].expose.name
        unknown-method-type               | $.methods[0].type               | unknown method type 'sonr' (known: action, broken-model, distance-angle,
        unknown-layer                     | $.methods[0].layer              | unknown layer 'sensors' (expected sensors_actuators, processing or virtual)
        layer-not-supported-by-type       | $.methods[2].layer              | type 'nearest-distance' cannot be placed in the virtual layer (it belongs in: processing)
        params-unknown-key                | $.methods[0].params.maxRange    | unknown parameter 'maxRange' (known: maxRangeM, minRangeM, use)
        params-string-for-number          | $.methods[0].params.maxRangeM   | must be a number, not a string ("5")
        params-rejected-naming-field      | $.methods[1].params.label       | label must not be blank
        params-not-above-declared-bound   | $.methods[0].params.maxRangeM   | must be greater than 0, was -1
        params-below-declared-minimum     | $.methods[0].params.minRangeM   | must be at least 0, was -0.5
        params-list-element-outside-range | $.methods[0].params.use[2]      | must be within [0, 31], was 40
        params-rejected-as-a-whole        | $.methods[0].params             | the minimum range must be below the maximum
        params-given-to-no-params-type    | $.methods[1].params.window      | unknown parameter 'window' (this type takes no parameters)
        params-primitive-missing          | $.methods[2].params.trackM      | required parameter 'trackM' is missing
        params-null-for-primitive         | $.methods[2].params.trackM      | must be a number, not null
        params-unknown-enum-value         | $.methods[2].params.stop        | must be one of HARD, SOFT, not a string ("BRAKE")
        params-bad-list-element           | $.methods[0].params.use[1]      | must be an integer, not a string ("two")
        params-number-for-string          | $.methods[1].params.label       | must be a string, not a number (5)
        params-number-for-boolean         | $.methods[1].params.verbose     | must be a boolean (true or false), not a number (1)
        params-not-an-object              | $.methods[0].params             | must be an object, not an array
        params-float-for-integer          | $.interfaces[0].params.sonarCount | must be an integer, not a number (8.5)
        driver-params-rejected            | $.interfaces[0].params.sonarCount | must be within [1, 32], was 40
        driver-cannot-be-made             | $.interfaces[0]                 | driver 'robot-sim' cannot be made: host unreachable.invalid is refused
        method-ports-cannot-be-listed     | $.methods[1]                    | type 'broken-model' cannot list its ports for these params: the model file is missing
        input-not-declared                | $.methods[0].inputs.extra       | 'extra' is not an input of type 'sonar' (inputs: ranges)
        required-input-unwired            | $.methods[1].inputs             | required input 'ranges' (vector) of type 'nearest-distance' is not wired
        unknown-method-reference          | $.methods[1].inputs.ranges      | unknown method 'sonr' (methods: nearest, sonar)
        unknown-output-reference          | $.methods[1].inputs.ranges      | method 'sonar' (type 'sonar') has no output 'range' (outputs: ranges)
        unknown-interface-reference       | $.methods[0].inputs.ranges      | unknown interface 'robo' (interfaces: robot)
        unknown-channel-reference         | $.methods[0].inputs.ranges      | interface 'robot' (driver 'robot-sim') has no channel 'sonars' (channels: battery, lines, link, motion, sonar, sonar-power)
        input-from-command-channel        | $.methods[0].inputs.ranges      | '@robot.motion' is a command channel; an input reads a reading channel
        command-to-reading-channel        | $.methods[2].commands.motion    | '@robot.sonar' is a reading channel; commands write a command channel
        command-key-not-an-output         | $.methods[2].commands.move      | 'move' is not an output of type 'wheels' (outputs: motion)
        kind-mismatch-channel-to-input    | $.methods[0].inputs.ranges      | kind mismatch: '@robot.battery' gives number but input 'ranges' takes vector
        kind-mismatch-output-to-input     | $.methods[2].inputs.nearest     | kind mismatch: 'sonar.ranges' gives vector but input 'nearest' takes number
        kind-mismatch-output-to-command   | $.methods[2].commands.motion    | kind mismatch: output 'motion' gives vector but '@robot.sonar-power' takes number
        channel-input-outside-sensors-layer | $.methods[0].inputs.ranges    | only a sensors_actuators method reads interface channels; 'nearest' is in the processing layer
        commands-outside-sensors-layer    | $.methods[0].commands.velocity  | only a sensors_actuators method writes interface commands; 'action' is in the virtual layer
        control-outside-virtual-layer     | $.methods[0].inputs.velocity    | only a virtual method takes values from control clients; 'safety' is in the processing layer
        expose-outside-virtual-layer      | $.methods[1].expose             | only a virtual method has a control socket; 'nearest' is in the processing layer
        layer-rule-sensors-to-virtual     | $.methods[1].inputs.in          | 'sonar.ranges' breaks the layer rule: a method exchanges data only with methods of its own layer or a neighbouring layer
        exposed-without-output-or-control | $.methods[3].expose             | an exposed method needs an output or a 'control' input, and 'sink' has neither
        host-without-port                 | $.methods[1].host               | 'worker1' names no port: write host:port
        worker-beyond-loopback-without-secret | $.methods[0].host           | worker 10.0.0.21:7600 is beyond loopback, where a worker requires the shared secret
        fallback-without-host             | $.methods[1].fallback           | a fallback needs a "host": it says what to do while that worker is lost
        fallback-unknown                  | $.methods[1].fallback           | 'remote' is not a fallback (write none or local)
        thread-unknown                    | $.methods[1].thread             | 'shared' is not a thread choice (write auto or own)
        expose-port-missing               | $.methods[0].expose.port        | required key 'port' is missing
        source-without-dot                | $.methods[1].inputs.ranges      | 'sonar' has no '.': write "methodId.output", "@interfaceId.channel" or "control"
        control-without-expose            | $.methods[0].inputs.action      | 'control' needs a control socket: give the method an 'expose'
        source-not-a-string               | $.methods[0].inputs.ranges      | must be a string, not a number (5)
        method-not-an-object              | $.methods[0]                    | must be an object, not a string ("sonar")
        wiring-cycle                      | $.methods[0].inputs.in          | 'b.out' closes a wiring cycle (a -> b -> a): a sample could go round it for ever. Rewire it, or declare it with "feedback": ["in"] on method 'a'
        wiring-cycle-of-one-method        | $.methods[0].inputs.in          | 'echo.out' closes a wiring cycle (echo -> echo)
        feedback-on-no-cycle              | $.methods[1].feedback[0]        | 'in' ('sonar.ranges') is on no wiring cycle: nothing to declare
        feedback-not-an-input             | $.methods[0].feedback[0]        | 'inn' is not a wired input of 'a' (wired: in)
        feedback-from-a-channel           | $.methods[0].feedback[0]        | 'ranges' reads '@robot.sonar': only a wire from a method's output can close a cycle
        """)
    void brokenConfigIsRejectedWithOneErrorAtItsPath(String file, String path, String message) throws URISyntaxException {
        Path config = Path.of(getClass().getResource("/configs/broken/" + file + ".json").toURI());

        ConfigException e = catchThrowableOfType(ConfigException.class, () -> loader.load(config));

        assertThat(e).as("%s must be rejected", file).isNotNull();
        List<ConfigError> errors = e.errors();
        assertThat(errors).as("errors of %s", file).hasSize(1);
        assertThat(errors.get(0).path()).isEqualTo(path);
        assertThat(errors.get(0).message()).contains(message);
    }
}
