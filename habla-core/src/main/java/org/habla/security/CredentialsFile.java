package org.habla.security;

import static java.nio.charset.StandardCharsets.UTF_8;

import com.fasterxml.jackson.core.JsonParser;
import com.fasterxml.jackson.core.JsonProcessingException;
import com.fasterxml.jackson.databind.DeserializationFeature;
import com.fasterxml.jackson.databind.JsonNode;
import com.fasterxml.jackson.databind.ObjectMapper;
import com.fasterxml.jackson.databind.json.JsonMapper;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.nio.file.attribute.PosixFileAttributeView;
import java.nio.file.attribute.PosixFilePermission;
import java.nio.file.attribute.PosixFilePermissions;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.Iterator;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.regex.Pattern;

/**
 * Reads a credentials file, which sits next to the config and holds what the config must not: each client's
 * token and roles, and the secret shared with workers. Strict like the config: every problem comes back with its
 * JSON path inside the file; a file others may read is refused.
 *
 * <pre>
 *   {
 *     "clients": [
 *       {"name": "mdb",    "token": "…at least 16 characters…", "roles": {"action": "command", "*": "read"}},
 *       {"name": "viewer", "token": "…",                        "roles": {"*": "read", "@status": "read"}}
 *     ],
 *     "workerSecret": "…at least 16 characters…",
 *     "bridges": {"room": {"say": "command"}}
 *   }
 * </pre>
 *
 * {@code bridges} gives each bridge of the config (by id) the sockets it may write actions to; with a credentials
 * file, a bridge may take actions only for sockets named here.
 *
 * A role key is a control socket's name, {@code "*"} for every socket not named, or {@code "@status"} for the
 * status endpoint (which takes {@code "read"} only).
 */
public final class CredentialsFile {

    /** The shortest token or worker secret accepted, in characters. */
    public static final int MIN_SECRET_CHARS = 16;
    /** The longest token or worker secret accepted, in characters. */
    public static final int MAX_SECRET_CHARS = 1_024;
    /** The largest credentials file read. */
    public static final long MAX_FILE_BYTES = 1 << 20;
    /** How a client's name is spelled. */
    public static final Pattern NAME = Pattern.compile("[A-Za-z0-9][A-Za-z0-9_.@-]{0,63}");

    private static final Set<String> ROOT_KEYS = Set.of("clients", "workerSecret", "bridges");
    private static final Set<String> CLIENT_KEYS = Set.of("name", "token", "roles");
    private static final ObjectMapper JSON = JsonMapper.builder()
            .enable(JsonParser.Feature.STRICT_DUPLICATE_DETECTION)
            .enable(DeserializationFeature.FAIL_ON_TRAILING_TOKENS)
            .build();

    /** What is wrong with a credentials file: each problem as {@code "$.clients[0].token: …"}. */
    public static final class Invalid extends Exception {
        private final List<String> problems;

        Invalid(List<String> problems) {
            super(String.join("; ", problems));
            this.problems = List.copyOf(problems);
        }

        public List<String> problems() {
            return problems;
        }
    }

    private CredentialsFile() {
    }

    /**
     * Reads and checks {@code file}.
     *
     * @param sockets the config's control socket names: a role for any other socket is an error
     */
    public static Credentials read(Path file, Set<String> sockets) throws Invalid {
        List<String> problems = new ArrayList<>();
        JsonNode root = parse(file, problems);
        if (root == null) {
            throw new Invalid(problems);
        }
        if (!root.isObject()) {
            throw new Invalid(List.of("$: must be a JSON object"));
        }
        unknownKeys(root, "$", ROOT_KEYS, problems);
        List<Credentials.Client> clients = new ArrayList<>();
        JsonNode list = root.get("clients");
        if (list != null && !list.isArray()) {
            problems.add("$.clients: must be an array");
        } else if (list != null) {
            Set<String> names = new HashSet<>();
            for (int i = 0; i < list.size(); i++) {
                Credentials.Client c = client(list.get(i), "$.clients[" + i + "]", sockets, problems);
                if (c != null && !names.add(c.name())) {
                    problems.add("$.clients[" + i + "].name: client '" + c.name() + "' is named twice");
                } else if (c != null) {
                    clients.add(c);
                }
            }
        }
        byte[] workerSecret = null;
        JsonNode ws = root.get("workerSecret");
        if (ws != null) {
            String s = secret(ws, "$.workerSecret", problems);
            workerSecret = s == null ? null : s.getBytes(UTF_8);
        }
        Map<String, Set<String>> bridges = new LinkedHashMap<>();
        JsonNode b = root.get("bridges");
        if (b != null && !b.isObject()) {
            problems.add("$.bridges: must be an object: bridge id -> {socket: \"command\"}");
        } else if (b != null) {
            b.properties().forEach(e -> bridges.put(e.getKey(), bridgeRoles(e.getValue(), "$.bridges." + e.getKey(),
                    sockets, problems)));
        }
        if (!problems.isEmpty()) {
            throw new Invalid(problems);
        }
        return new Credentials(clients, workerSecret, bridges);
    }

    /**
     * Reads a worker's secret: a file whose first line is the secret, readable by its owner only.
     *
     * @throws Invalid naming what is wrong, never the secret
     */
    public static WorkerSecret readWorkerSecret(Path file) throws Invalid {
        List<String> problems = new ArrayList<>();
        String text = text(file, problems);
        if (text == null) {
            throw new Invalid(problems);
        }
        String line = text.lines().findFirst().orElse("").strip();
        if (line.length() < MIN_SECRET_CHARS || line.length() > MAX_SECRET_CHARS) {
            throw new Invalid(List.of("$: the secret on its first line must have " + MIN_SECRET_CHARS + " to "
                    + MAX_SECRET_CHARS + " characters, had " + line.length()));
        }
        return new WorkerSecret(line.getBytes(UTF_8));
    }

    private static JsonNode parse(Path file, List<String> problems) {
        String text = text(file, problems);
        if (text == null) {
            return null;
        }
        try {
            return JSON.readTree(text);
        } catch (JsonProcessingException e) {
            // Jackson's message may quote the file's text, which holds secrets: give the place only.
            var at = e.getLocation();
            problems.add("$: invalid JSON" + (at == null ? "" : " at line " + at.getLineNr() + ", column "
                    + at.getColumnNr()));
            return null;
        }
    }

    /** The file's text if it exists, is small, is UTF-8 and only its owner may read it. */
    private static String text(Path file, List<String> problems) {
        try {
            if (Files.size(file) > MAX_FILE_BYTES) {
                problems.add("$: larger than " + MAX_FILE_BYTES + " bytes");
                return null;
            }
            PosixFileAttributeView posix = Files.getFileAttributeView(file, PosixFileAttributeView.class);
            if (posix != null) {
                Set<PosixFilePermission> p = posix.readAttributes().permissions();
                if (p.stream().anyMatch(x -> x.name().startsWith("GROUP_") || x.name().startsWith("OTHERS_"))) {
                    problems.add("$: others may read it (mode " + PosixFilePermissions.toString(p)
                            + "); it holds secrets: chmod 600 " + file);
                    return null;
                }
            }
            return UTF_8.newDecoder().decode(java.nio.ByteBuffer.wrap(Files.readAllBytes(file))).toString();
        } catch (NoSuchFileException e) {
            problems.add("$: no such file (" + file + ")");
        } catch (java.nio.charset.CharacterCodingException e) {
            problems.add("$: not UTF-8 text");
        } catch (IOException e) {
            problems.add("$: cannot read it: " + e.getMessage());
        }
        return null;
    }

    private static Credentials.Client client(JsonNode n, String path, Set<String> sockets, List<String> problems) {
        if (n == null || !n.isObject()) {
            problems.add(path + ": must be an object with \"name\", \"token\" and \"roles\"");
            return null;
        }
        unknownKeys(n, path, CLIENT_KEYS, problems);
        int before = problems.size();
        JsonNode nameNode = n.get("name");
        String name = null;
        if (nameNode == null || !nameNode.isTextual() || !NAME.matcher(nameNode.asText()).matches()) {
            problems.add(path + ".name: must be a name of 1 to 64 letters, digits, '_', '.', '@' or '-'"
                    + " starting with a letter or digit");
        } else {
            name = nameNode.asText();
        }
        String token = n.has("token") ? secret(n.get("token"), path + ".token", problems) : null;
        if (!n.has("token")) {
            problems.add(path + ".token: missing");
        }
        Map<String, Role> roles = new LinkedHashMap<>();
        JsonNode r = n.get("roles");
        if (r == null || !r.isObject() || r.isEmpty()) {
            problems.add(path + ".roles: must be an object giving at least one port a role, e.g. {\"*\": \"read\"}");
        } else {
            for (Iterator<Map.Entry<String, JsonNode>> it = r.fields(); it.hasNext(); ) {
                Map.Entry<String, JsonNode> e = it.next();
                String key = e.getKey();
                String at = path + ".roles." + key;
                if (!key.equals(Principal.ANY) && !key.equals(Principal.STATUS) && !sockets.contains(key)) {
                    problems.add(at + ": the config exposes no socket '" + key + "'; keys are socket names, \"*\" "
                            + "and \"@status\"; sockets are " + sockets.stream().sorted().toList());
                    continue;
                }
                Role role = e.getValue().isTextual() ? Role.fromFile(e.getValue().asText()).orElse(null) : null;
                if (role == null) {
                    problems.add(at + ": must be \"read\" or \"command\", was " + e.getValue());
                } else if (key.equals(Principal.STATUS) && role != Role.READ) {
                    problems.add(at + ": the status endpoint takes \"read\" only");
                } else {
                    roles.put(key, role);
                }
            }
        }
        if (problems.size() != before || name == null || token == null) {
            return null;
        }
        return new Credentials.Client(name, Credentials.digest(token), roles);
    }

    private static Set<String> bridgeRoles(JsonNode n, String path, Set<String> sockets, List<String> problems) {
        Set<String> commands = new java.util.TreeSet<>();
        if (!n.isObject()) {
            problems.add(path + ": must be an object: socket -> \"command\"");
            return commands;
        }
        n.properties().forEach(e -> {
            if (!sockets.contains(e.getKey())) {
                problems.add(path + "." + e.getKey() + ": the config exposes no socket '" + e.getKey() + "'");
            } else if (!e.getValue().isTextual() || !e.getValue().asText().equals("command")) {
                problems.add(path + "." + e.getKey() + ": must be \"command\" (a bridge reads what its config "
                        + "publishes), was " + e.getValue());
            } else {
                commands.add(e.getKey());
            }
        });
        return commands;
    }

    /** A token or secret's text; the problem never quotes it. */
    private static String secret(JsonNode n, String path, List<String> problems) {
        if (!n.isTextual()) {
            problems.add(path + ": must be a string");
            return null;
        }
        String s = n.asText();
        if (s.length() < MIN_SECRET_CHARS || s.length() > MAX_SECRET_CHARS) {
            problems.add(path + ": must have " + MIN_SECRET_CHARS + " to " + MAX_SECRET_CHARS + " characters, had "
                    + s.length() + " (make one with: openssl rand -base64 24)");
            return null;
        }
        return s;
    }

    private static void unknownKeys(JsonNode n, String path, Set<String> allowed, List<String> problems) {
        n.fieldNames().forEachRemaining(k -> {
            if (!allowed.contains(k)) {
                problems.add(path + "." + k + ": unknown key; allowed are " + allowed.stream().sorted().toList());
            }
        });
    }
}
