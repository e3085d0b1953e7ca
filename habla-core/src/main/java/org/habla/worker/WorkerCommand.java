package org.habla.worker;

import java.io.IOException;
import java.io.PrintWriter;
import java.util.concurrent.Callable;
import java.util.concurrent.CountDownLatch;
import org.habla.command.ExitCodes;
import org.habla.net.Limits;
import org.habla.graph.EngineClock;
import org.habla.net.WorkerProtocol;
import org.habla.plugin.PluginRegistry;
import picocli.CommandLine.Command;
import picocli.CommandLine.Model.CommandSpec;
import picocli.CommandLine.Option;
import picocli.CommandLine.Spec;

/**
 * {@code habla worker --port P [--bind ADDR] [--secret-file FILE] [--tls-cert PEM --tls-key PEM]}: runs, on this computer, the methods a daemon's config
 * places here with {@code "host": "this-computer:P"}. It needs no config: the daemon sends each method's
 * type and params, and the worker makes it from the method types it has (the same plugins as the daemon).
 */
@Command(name = "worker", mixinStandardHelpOptions = true,
        description = "Run methods for a HABLA daemon on this computer (a config's \"host\": \"this-computer:PORT\").")
public final class WorkerCommand implements Callable<Integer> {

    @Spec
    private CommandSpec spec;

    @Option(names = "--port", paramLabel = "P", defaultValue = "" + WorkerProtocol.DEFAULT_PORT,
            description = "The TCP port to listen on (default ${DEFAULT-VALUE}).")
    private int port;

    @Option(names = "--bind", paramLabel = "ADDR", defaultValue = "127.0.0.1",
            description = "The address to listen on (default ${DEFAULT-VALUE}: this computer only); beyond loopback "
                    + "it needs --secret-file.")
    private String bind;

    @Option(names = "--secret-file", paramLabel = "FILE",
            description = "A file (readable by its owner only) whose first line is the secret a daemon must prove "
                    + "before it may place a method: the \"workerSecret\" of the daemon's credentials file.")
    private java.nio.file.Path secretFile;

    @Option(names = "--tls-cert", paramLabel = "PEM", description = "Speak TLS with this certificate (with --tls-key).")
    private java.nio.file.Path tlsCertificate;

    @Option(names = "--tls-key", paramLabel = "PEM", description = "The TLS certificate's unencrypted PKCS#8 key.")
    private java.nio.file.Path tlsKey;

    @Option(names = "--time-scale", paramLabel = "S", defaultValue = "1",
            description = "Run the methods' clock S times faster than the wall clock, as the daemon's --time-scale.")
    private double timeScale;

    @Option(names = "--max-methods", paramLabel = "N", defaultValue = "" + Limits.CLIENTS_PER_PORT,
            description = "Connections (methods placed or being placed) at once, 1..1024 (default ${DEFAULT-VALUE}); "
                    + "at the cap a connection that placed nothing gives way to a newcomer.")
    private int maxMethods;

    @Override
    public Integer call() throws InterruptedException {
        PrintWriter err = spec.commandLine().getErr();
        if (port < 0 || port > 65_535) {
            err.println("habla worker: --port must be in 0..65535, was " + port);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if (!(timeScale >= 1) || !Double.isFinite(timeScale)) {
            err.println("habla worker: --time-scale must be 1 or more, was " + timeScale);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if (maxMethods < 1 || maxMethods > 1_024) {
            err.println("habla worker: --max-methods must be in 1..1024, was " + maxMethods);
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        org.habla.security.WorkerSecret secret = null;
        if (secretFile != null) {
            try {
                secret = org.habla.security.CredentialsFile.readWorkerSecret(secretFile);
            } catch (org.habla.security.CredentialsFile.Invalid e) {
                err.println("habla worker: --secret-file " + secretFile + " " + e.getMessage());
                err.flush();
                return ExitCodes.USAGE_OR_CONFIG;
            }
        }
        if (secret == null && !org.habla.config.SecurityConfig.isLoopback(bind)) {
            err.println("habla worker: --bind " + bind + " is beyond loopback, and without --secret-file any daemon "
                    + "(or anyone) on that network could place methods here; give --secret-file FILE with the "
                    + "daemon's workerSecret (docs/security.md)");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        if ((tlsCertificate == null) != (tlsKey == null)) {
            err.println("habla worker: --tls-cert and --tls-key go together");
            err.flush();
            return ExitCodes.USAGE_OR_CONFIG;
        }
        org.habla.security.Tls tls = null;
        if (tlsCertificate != null) {
            try {
                tls = org.habla.security.Tls.server(tlsCertificate, tlsKey);
            } catch (IOException e) {
                err.println("habla worker: " + e.getMessage());
                err.flush();
                return ExitCodes.USAGE_OR_CONFIG;
            }
        }
        PluginRegistry registry = PluginRegistry.discover(Thread.currentThread().getContextClassLoader());
        EngineClock clock = timeScale == 1 ? EngineClock.system() : EngineClock.scaled(timeScale);
        WorkerServer server = new WorkerServer(registry, bind, port, clock, limits(maxMethods), secret, tls);
        try {
            server.start();
        } catch (IOException e) {
            err.println("habla worker: " + e.getMessage());
            err.flush();
            return ExitCodes.RUNTIME_FAILURE;
        }
        spec.commandLine().getOut().println("HABLA worker on " + bind + ":" + server.port() + ", "
                + registry.methods().size() + " method types");
        spec.commandLine().getOut().flush();
        CountDownLatch stopped = new CountDownLatch(1);
        Runtime.getRuntime().addShutdownHook(new Thread(() -> {
            server.close();
            clock.close();
            stopped.countDown();
            Runtime.getRuntime().halt(ExitCodes.OK);
        }, "habla-worker-shutdown"));
        stopped.await();
        return ExitCodes.OK;
    }

    /** The default limits of every socket, with the cap on connections this worker was given. */
    static Limits limits(int maxMethods) {
        return Limits.DEFAULTS.withCaps(maxMethods, Limits.DEFAULTS.maxPendingPerPort());
    }
}
