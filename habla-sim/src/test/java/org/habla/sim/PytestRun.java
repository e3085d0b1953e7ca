package org.habla.sim;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.TimeUnit;

/**
 * One pytest run of a Python package's tests, as a JUnit test starts it: the tests start {@code habla} with this
 * build's classes (HABLA_COMMAND, the java command of this JVM's class path) on a free block of ports
 * (HABLA_TEST_PORT_OFFSET); the output goes to a log the assertions quote. Bounded: a run past
 * {@link #LIMIT_S} is killed with everything it started.
 */
final class PytestRun {

    static final long LIMIT_S = 360;

    private final List<String> python;
    private final Path workDir;
    private final Path log;
    private final Map<String, String> env = new java.util.HashMap<>();
    private boolean finished;
    private int exitCode = -1;

    private PytestRun(List<String> python, Path workDir, Path tmp) {
        this.python = python;
        this.workDir = workDir;
        this.log = tmp.resolve("pytest.log");
    }

    static PytestRun of(List<String> python, Path workDir, Path tmp) {
        return new PytestRun(python, workDir, tmp);
    }

    PytestRun env(String key, String value) {
        env.put(key, value);
        return this;
    }

    /** Runs pytest on {@code tests} and waits for it (bounded). */
    PytestRun start(Path tests) throws IOException, InterruptedException {
        List<String> cmd = new ArrayList<>(python);
        cmd.addAll(List.of("-m", "pytest", "-v", "-p", "no:cacheprovider", tests.toString()));
        ProcessBuilder pb = new ProcessBuilder(cmd).directory(workDir.toFile()).redirectErrorStream(true)
                .redirectOutput(log.toFile());
        pb.environment().put("PYTHONDONTWRITEBYTECODE", "1");
        pb.environment().put("HABLA_COMMAND", hablaCommand());
        pb.environment().put("HABLA_TEST_PORT_OFFSET", "" + PortBlock.freeOffset());
        pb.environment().putAll(env);
        Process p = pb.start();
        finished = p.waitFor(LIMIT_S, TimeUnit.SECONDS);
        if (!finished) {
            p.descendants().forEach(ProcessHandle::destroyForcibly);
            p.destroyForcibly().waitFor(10, TimeUnit.SECONDS);
        } else {
            exitCode = p.exitValue();
        }
        return this;
    }

    boolean finished() {
        return finished;
    }

    int exitCode() {
        return exitCode;
    }

    String log() throws IOException {
        return Files.readString(log, StandardCharsets.UTF_8);
    }

    /** The java command running {@code habla} with this JVM's class path, as a JSON list. */
    static String hablaCommand() {
        List<String> cmd = List.of(Path.of(System.getProperty("java.home"), "bin", "java").toString(), "-Xmx512m",
                "-cp", System.getProperty("java.class.path"), "org.habla.cli.Habla");
        StringBuilder json = new StringBuilder("[");
        for (String part : cmd) {
            json.append(json.length() > 1 ? "," : "").append('"')
                    .append(part.replace("\\", "\\\\").replace("\"", "\\\"")).append('"');
        }
        return json.append(']').toString();
    }
}
