package lt.spindulys;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assertions.fail;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayDeque;
import java.util.ArrayList;
import java.util.Deque;
import java.util.List;
import java.util.Map;
import java.util.Set;
import java.util.TreeMap;
import java.util.TreeSet;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import org.junit.jupiter.api.Test;

/**
 * Keeps the package graph of src/main one-way (math at the bottom, cli at the top): reads every main source file's
 * imports and fully qualified {@code lt.spindulys.x.Y} references and fails on any cycle, naming it with one
 * source line per edge so the fix can start from the message. The two front ends at the top are held to the arrows
 * they are meant to have: the bench to the exported API and the few internals its package-info names, the command
 * line to the packages it uses now, none of the per-ray machinery.
 */
class PackageCyclesTest {

    private static final Path MAIN = Path.of("src/main/java/lt/spindulys");

    /** A reference to another package: {@code lt.spindulys.pkg.Type}, or {@code lt.spindulys.pkg.*}. */
    private static final Pattern REFERENCE = Pattern.compile("\\blt\\.spindulys\\.([a-z][a-z0-9_]*)\\.([A-Z][A-Za-z0-9_]*|\\*)");

    @Test
    void packageGraphHasNoCycle() throws IOException {
        Map<String, Map<String, String>> graph = graph(MAIN);
        assertTrue(graph.size() > 5, "found the main packages under " + MAIN.toAbsolutePath());
        List<String> cycles = cycles(graph);
        if (!cycles.isEmpty()) {
            fail("the package graph of src/main has cycles (math must stay at the bottom, cli at the top):\n  " + String.join("\n  ", cycles));
        }
    }

    /**
     * The bench measures the library as a user would, through the exported packages (read from module-info), and
     * beyond them only what its package-info names and why: {@code frontend} (the version, the peak heap),
     * {@code files} (atomic writes of generated inputs), {@code limits} (patch sizes in the library's words) and
     * {@code viewer} (the row that times the viewer's rasterizer). It never uses the command line.
     */
    @Test
    void theBenchUsesTheExportedApi() throws IOException {
        Set<String> allowed = new TreeSet<>(exported());
        allowed.addAll(Set.of("frontend", "files", "limits", "viewer"));
        assertUsesOnly("bench", allowed);
    }

    /**
     * The command line: {@code render} and {@code io} (the render job, the readers), {@code bench} (one dispatch),
     * {@code frontend} (failure lines, version, peak heap), and what its commands still reach for themselves: scene,
     * image, camera, math and limits in the render command's options and checks, files, mesh and subdiv in
     * {@code render subdivide}, plugin and viewer in {@code render view}. Not the per-ray machinery (accel, trace,
     * shading, sampling, adaptive) nor materials and textures: a command that needs more goes through the library.
     */
    @Test
    void theCommandLineUsesTheRenderJobTheReadersAndItsCommandsNeeds() throws IOException {
        assertUsesOnly("cli", Set.of("render", "io", "bench", "frontend", "scene", "image", "camera", "math", "limits",
                "files", "mesh", "subdiv", "plugin", "viewer"));
    }

    private static void assertUsesOnly(String from, Set<String> allowed) throws IOException {
        Map<String, String> uses = graph(MAIN).get(from);
        assertTrue(uses != null && !uses.isEmpty(), "found the package " + from);
        List<String> beyond = new ArrayList<>();
        for (Map.Entry<String, String> e : uses.entrySet()) {
            if (!allowed.contains(e.getKey())) {
                beyond.add(e.getValue());
            }
        }
        assertTrue(beyond.isEmpty(), from + " uses packages beyond " + new TreeSet<>(allowed) + ":\n  " + String.join("\n  ", beyond));
    }

    /** The packages module-info exports, without the prefix. */
    private static Set<String> exported() throws IOException {
        Set<String> exported = new TreeSet<>();
        Matcher m = Pattern.compile("(?m)^\\s*exports\\s+lt\\.spindulys\\.([a-z][a-z0-9_]*)\\s*;")
                .matcher(code(Files.readString(MAIN.getParent().getParent().resolve("module-info.java"), StandardCharsets.UTF_8)));
        while (m.find()) {
            exported.add(m.group(1));
        }
        assertTrue(exported.size() > 5, "read the exports of module-info.java: " + exported);
        return exported;
    }

    @Test
    void theCheckNamesACycleWithItsEvidence() {
        Map<String, Map<String, String>> graph = new TreeMap<>();
        graph.computeIfAbsent("scene", k -> new TreeMap<>()).put("accel", "scene/Scene.java imports accel.Bvh");
        graph.computeIfAbsent("accel", k -> new TreeMap<>()).put("scene", "accel/Bvh.java imports scene.Hit");
        graph.computeIfAbsent("accel", k -> new TreeMap<>()).put("math", "accel/Bvh.java imports math.Ray");
        graph.computeIfAbsent("math", k -> new TreeMap<>());
        assertEquals(List.of("accel -> scene -> accel: accel/Bvh.java imports scene.Hit; scene/Scene.java imports accel.Bvh"),
                cycles(graph));
    }

    /** For each package, the packages it uses, each with the first place that shows it. */
    private static Map<String, Map<String, String>> graph(Path root) throws IOException {
        Map<String, Map<String, String>> graph = new TreeMap<>();
        List<Path> files;
        try (Stream<Path> walk = Files.walk(root)) {
            files = walk.filter(p -> p.toString().endsWith(".java")).sorted().toList();
        }
        for (Path file : files) {
            String relative = root.relativize(file).toString().replace('\\', '/');
            int slash = relative.indexOf('/');
            if (slash < 0) {
                continue;
            }
            String from = relative.substring(0, slash);
            Map<String, String> uses = graph.computeIfAbsent(from, k -> new TreeMap<>());
            Matcher m = REFERENCE.matcher(code(Files.readString(file, StandardCharsets.UTF_8)));
            while (m.find()) {
                String to = m.group(1);
                if (!to.equals(from)) {
                    uses.putIfAbsent(to, relative + " imports " + to + "." + m.group(2));
                }
            }
        }
        return graph;
    }

    /** The source without comments and string or character literals, so prose naming a class adds no edge. */
    private static String code(String source) {
        StringBuilder out = new StringBuilder(source.length());
        int i = 0;
        int n = source.length();
        while (i < n) {
            char c = source.charAt(i);
            if (c == '/' && i + 1 < n && source.charAt(i + 1) == '/') {
                while (i < n && source.charAt(i) != '\n') {
                    i++;
                }
            } else if (c == '/' && i + 1 < n && source.charAt(i + 1) == '*') {
                int end = source.indexOf("*/", i + 2);
                i = end < 0 ? n : end + 2;
                out.append(' ');
            } else if (source.startsWith("\"\"\"", i)) {
                int end = source.indexOf("\"\"\"", i + 3);
                i = end < 0 ? n : end + 3;
                out.append("\"\"");
            } else if (c == '"' || c == '\'') {
                i++;
                while (i < n && source.charAt(i) != c && source.charAt(i) != '\n') {
                    i += source.charAt(i) == '\\' ? 2 : 1;
                }
                i++;
                out.append(c).append(c);
            } else {
                out.append(c);
                i++;
            }
        }
        return out.toString();
    }

    /**
     * For each strongly connected group of packages (Tarjan), a shortest cycle through each of its packages, each
     * cycle once, as "a -> b -> a: evidence; ...": a group is usually several cycles, and each needs its own cut.
     */
    static List<String> cycles(Map<String, Map<String, String>> graph) {
        List<String> cycles = new ArrayList<>();
        java.util.Set<String> seen = new java.util.HashSet<>();
        for (TreeSet<String> component : components(graph)) {
            for (String start : component) {
                List<String> path = shortestCycle(graph, component, start);
                // The same cycle found from another of its packages is a rotation: key it by its sorted edges.
                TreeSet<String> edges = new TreeSet<>();
                String from = start;
                for (String to : path) {
                    edges.add(from + ">" + to);
                    from = to;
                }
                if (!seen.add(edges.toString())) {
                    continue;
                }
                StringBuilder names = new StringBuilder(start);
                List<String> evidence = new ArrayList<>();
                from = start;
                for (String to : path) {
                    names.append(" -> ").append(to);
                    evidence.add(graph.get(from).get(to));
                    from = to;
                }
                cycles.add(names + ": " + String.join("; ", evidence));
            }
        }
        return cycles;
    }

    /** The packages after {@code start} on a shortest way back to it inside the component (breadth first). */
    private static List<String> shortestCycle(Map<String, Map<String, String>> graph, TreeSet<String> component, String start) {
        Map<String, String> previous = new TreeMap<>();
        Deque<String> queue = new ArrayDeque<>(List.of(start));
        while (!queue.isEmpty()) {
            String at = queue.removeFirst();
            for (String next : graph.getOrDefault(at, Map.of()).keySet()) {
                if (!component.contains(next)) {
                    continue;
                }
                if (next.equals(start)) {
                    List<String> path = new ArrayList<>(List.of(start));
                    for (String p = at; !p.equals(start); p = previous.get(p)) {
                        path.add(0, p);
                    }
                    return path;
                }
                if (!previous.containsKey(next)) {
                    previous.put(next, at);
                    queue.addLast(next);
                }
            }
        }
        throw new AssertionError("no cycle through " + start);
    }

    /** Strongly connected components with more than one package (a package's use of itself is not recorded). */
    private static List<TreeSet<String>> components(Map<String, Map<String, String>> graph) {
        Map<String, Integer> index = new TreeMap<>();
        Map<String, Integer> low = new TreeMap<>();
        Deque<String> stack = new ArrayDeque<>();
        List<TreeSet<String>> found = new ArrayList<>();
        for (String node : graph.keySet()) {
            if (!index.containsKey(node)) {
                connect(graph, node, index, low, stack, found);
            }
        }
        return found;
    }

    // The package graph has a dozen nodes, so recursion depth here is bounded by the code base, not by input.
    private static void connect(Map<String, Map<String, String>> graph, String node, Map<String, Integer> index,
            Map<String, Integer> low, Deque<String> stack, List<TreeSet<String>> found) {
        index.put(node, index.size());
        low.put(node, index.get(node));
        stack.push(node);
        for (String next : graph.getOrDefault(node, Map.of()).keySet()) {
            if (!index.containsKey(next)) {
                connect(graph, next, index, low, stack, found);
                low.put(node, Math.min(low.get(node), low.get(next)));
            } else if (stack.contains(next)) {
                low.put(node, Math.min(low.get(node), index.get(next)));
            }
        }
        if (low.get(node).equals(index.get(node))) {
            TreeSet<String> component = new TreeSet<>();
            String member;
            do {
                member = stack.pop();
                component.add(member);
            } while (!member.equals(node));
            if (component.size() > 1) {
                found.add(component);
            }
        }
    }
}
