package org.habla.cli;

import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import java.io.BufferedReader;
import java.io.IOException;
import java.io.InputStreamReader;
import java.io.PrintWriter;
import java.net.InetSocketAddress;
import java.net.Socket;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.concurrent.Callable;
import org.habla.command.ExitCodes;
import org.habla.config.ConfigException;
import org.habla.config.ConfigLoader;
import org.habla.config.HablaConfig;
import org.habla.config.StatusConfig;
import org.habla.net.BindAddress;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;
import picocli.CommandLine.Spec;

/**
 * {@code habla status [CONFIG]}: reads a running daemon's status endpoint and prints it as tables (or JSON). Given
 * the daemon's config, it asks where the config says the endpoint is: {@code status.port} on {@code status.bind}
 * (the loopback address of a wildcard), over TLS with the certificate of {@code security.tls} when
 * {@code status.tls}; {@code --host}, {@code --port} and {@code --tls-trust} still win.
 */
@Command(name = "status", mixinStandardHelpOptions = true,
        description = "Show a running daemon's links, devices, methods (and why they are stale), sockets, bridges and "
                + "the watchdog.")
public final class StatusCommand implements Callable<Integer> {

    /** How long to wait for the endpoint to accept the connection. */
    private static final int CONNECT_MILLIS = 2_000;
    /** How long to wait for each line of the answer (and the TLS handshake). */
    private static final int READ_MILLIS = 5_000;

    @Spec
    private CommandSpec spec;

    @Parameters(index = "0", arity = "0..1", paramLabel = "CONFIG",
            description = "The daemon's config: find the status endpoint from its status section.")
    private Path configArgument;

    @Option(names = "--config", paramLabel = "FILE", description = "The daemon's config (the same as CONFIG).")
    private Path configOption;

    @Option(names = "--host", description = "The daemon's host (default: from the config, else 127.0.0.1).")
    private String host;

    @Option(names = "--port", description = "The status port (default: from the config, else 7099).")
    private Integer port;

    @Option(names = "--json", description = "Print the raw JSON snapshot.")
    private boolean json;

    @Option(names = "--client", paramLabel = "NAME", defaultValue = "${env:HABLA_CLIENT}",
            description = "The client name to authenticate as, where the endpoint requires it (or HABLA_CLIENT).")
    private String client;

    @Option(names = "--tls-trust", paramLabel = "PEM",
            description = "The endpoint speaks TLS: trust this certificate (the lab's, see docs/security.md; default: "
                    + "the config's security.tls certificate when its status has tls).")
    private Path tlsTrust;

    @Option(names = "--token-file", paramLabel = "FILE",
            description = "A file whose first line is the client's token (else the HABLA_TOKEN environment variable).")
    private Path tokenFile;

    private final PluginRegistry registry;

    public StatusCommand() {
        this(null);
    }

    /** A command that reads configs against exactly these plugins instead of the ones on the class path. */
    public StatusCommand(PluginRegistry registry) {
        this.registry = registry;
    }

    /** Where to ask: the address, the port, the certificate to trust (null: plain TCP), and where that came from. */
    private record Endpoint(String host, int port, Path trust, String from) {
    }

    @Override
    public Integer call() {
        PrintWriter out = spec.commandLine().getOut();
        PrintWriter err = spec.commandLine().getErr();
        if (configArgument != null && configOption != null && !configArgument.equals(configOption)) {
            err.println("habla status: give the config once: CONFIG or --config FILE");
            return ExitCodes.USAGE_OR_CONFIG;
        }
        Path config = configArgument != null ? configArgument : configOption;
        Endpoint endpoint;
        if (config == null) {
            endpoint = new Endpoint(host != null ? host : BindAddress.DEFAULT,
                    port != null ? port : StatusConfig.DEFAULTS.port(), tlsTrust,
                    port != null ? "" : "; give the daemon's config to find its port: habla status CONFIG");
        } else {
            HablaConfig cfg;
            try {
                cfg = new ConfigLoader(registry != null ? registry
                        : PluginRegistry.discover(Thread.currentThread().getContextClassLoader())).load(config);
            } catch (ConfigException e) {
                ConfigReport.errors(err, config, e.errors(), "its status endpoint cannot be found");
                return ExitCodes.USAGE_OR_CONFIG;
            }
            StatusConfig st = cfg.status();
            if (st.port() == 0 && port == null) {
                err.println("habla status: " + config + " turns the status endpoint off (status.port 0)");
                return ExitCodes.USAGE_OR_CONFIG;
            }
            try {
                endpoint = new Endpoint(host != null ? host : BindAddress.of(st.bind()).local().getHostAddress(),
                        port != null ? port : st.port(), tlsTrust != null ? tlsTrust
                                : st.tls() ? cfg.security().tlsCertificate() : null,
                        " — from status.bind and status.port of " + config);
            } catch (IOException e) {
                err.println("habla status: status.bind of " + config + ": " + e.getMessage());
                return ExitCodes.USAGE_OR_CONFIG;
            }
        }
        JsonNode status;
        try {
            status = fetch(endpoint, err);
        } catch (IOException e) {
            err.println("habla status: no daemon status at " + endpoint.host() + ":" + endpoint.port() + " ("
                    + e.getMessage() + ")" + endpoint.from());
            return ExitCodes.RUNTIME_FAILURE;
        }
        if (status == null) {
            return ExitCodes.RUNTIME_FAILURE;
        }
        if (json) {
            out.println(status.toPrettyString());
        } else {
            StatusTables.print(status, out);
        }
        out.flush();
        return ExitCodes.OK;
    }

    /** Reads the snapshot, authenticating where the endpoint asks; null after telling {@code err} why not. */
    private JsonNode fetch(Endpoint endpoint, PrintWriter err) throws IOException {
        String host = endpoint.host();
        int port = endpoint.port();
        try (Socket plain = new Socket()) {
            plain.connect(new InetSocketAddress(host, port), CONNECT_MILLIS);
            plain.setSoTimeout(READ_MILLIS);
            Socket s = endpoint.trust() == null ? plain
                    : org.habla.security.Tls.client(endpoint.trust()).connect(plain, host, port, READ_MILLIS);
            BufferedReader in = new BufferedReader(new InputStreamReader(s.getInputStream(), StandardCharsets.UTF_8));
            String line = in.readLine();
            JsonNode first = line == null ? null : new ObjectMapper().readTree(line);
            if (first != null && first.path("type").asText().equals("hello")
                    && first.path("auth").asText().equals("required")) {
                String token = token();
                if (client == null || client.isBlank() || token == null) {
                    err.println("habla status: the status endpoint at " + host + ":" + port + " requires "
                            + "authentication: give --client NAME and --token-file FILE (or HABLA_CLIENT, HABLA_TOKEN)");
                    return null;
                }
                s.getOutputStream().write((new ObjectMapper().createObjectNode().put("op", "auth")
                        .put("client", client).put("token", token).toString() + "\n").getBytes(StandardCharsets.UTF_8));
                s.getOutputStream().flush();
                line = in.readLine();
                JsonNode answer = line == null ? null : new ObjectMapper().readTree(line);
                if (answer != null && answer.path("type").asText().equals("error")) {
                    err.println("habla status: refused: " + answer.path("code").asText() + ": "
                            + answer.path("message").asText());
                    return null;
                }
            }
            if (line == null) {
                err.println("habla status: the daemon at " + host + ":" + port + " closed without a status line");
                return null;
            }
            return new ObjectMapper().readTree(line);
        }
    }

    /** The token from --token-file, or HABLA_TOKEN; null when neither is given. */
    private String token() throws IOException {
        if (tokenFile != null) {
            return java.nio.file.Files.readString(tokenFile).lines().findFirst().orElse("").strip();
        }
        String env = System.getenv("HABLA_TOKEN");
        return env == null || env.isBlank() ? null : env.strip();
    }
}
