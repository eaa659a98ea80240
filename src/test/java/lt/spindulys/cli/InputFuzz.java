package lt.spindulys.cli;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.io.PrintStream;
import java.nio.ByteBuffer;
import java.nio.ByteOrder;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Comparator;
import java.util.List;
import java.util.Random;
import java.util.concurrent.atomic.AtomicReference;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;

/**
 * Seeded hostile input for the whole command line: each case copies one scene of scenes/ (made
 * small) with its meshes and textures, mutates the scene or one of its files, renders it in
 * process and checks the promise "it renders, or it fails with exit 2, one located line and no
 * output file". Run by {@link InputFuzzTest} in a child JVM with a small heap; also a program, for
 * longer runs by hand:
 *
 * <pre>java -Xmx192m --add-modules jdk.incubator.vector -cp target/classes:target/test-classes \
 *     lt.spindulys.cli.InputFuzz SEED COUNT REPO_ROOT WORK_DIR</pre>
 *
 * <p>It prints one {@code FAIL} line per broken promise (with the case number and the mutations,
 * enough to reproduce it with the same seed) and a {@code SUMMARY} line last. With
 * {@code -Dfuzz.verbose=true} it also prints a {@code CASE} line for every case: its scene, its
 * mutations, the outcome and the time it took (to see what a seed covers). With
 * {@code -Dfuzz.keep=DIR} the files of each failing case are kept in DIR/caseN, to reproduce it with
 * {@code render DIR/caseN/scenes/SCENE -o out.pfm}. {@code -Dfuzz.repeats=2,1000,20000} sets how many
 * times a repeated line is repeated (the default keeps each case within about a second).
 */
public final class InputFuzz {
    private InputFuzz() {}

    /** A render that takes longer than this is interrupted: a slow valid scene is not a failure, a hang shows as one. */
    static final long TIMEOUT_MS = 8000;

    private static final boolean VERBOSE = Boolean.getBoolean("fuzz.verbose");
    private static final String KEEP = System.getProperty("fuzz.keep");
    /** How many times the line-repeating mutation repeats a line; {@code -Dfuzz.repeats=2,1000,20000} for heavier runs by hand. */
    private static final int[] REPEATS = java.util.Arrays.stream(System.getProperty("fuzz.repeats", "2,100,1000").split(","))
            .mapToInt(Integer::parseInt).toArray();

    /** file:line:column: message, all on one line. */
    private static final Pattern LOCATED = Pattern.compile("^\\S[^\\n]*?:\\d+:\\d+: \\S[^\\n]*$");

    public static void main(String[] args) throws Exception {
        long seed = Long.parseLong(args[0]);
        int count = Integer.parseInt(args[1]);
        Path repo = Path.of(args[2]), work = Path.of(args[3]);
        Counts c = run(seed, count, repo, work, System.out);
        System.out.println("SUMMARY cases=" + c.cases + " rendered=" + c.rendered + " refused=" + c.refused
                + " interrupted=" + c.interrupted + " failures=" + c.failures);
        System.out.flush();
        // Render threads of an interrupted case may still be winding down.
        System.exit(0);
    }

    static final class Counts {
        int cases, rendered, refused, interrupted, failures;
    }

    /** Runs {@code count} cases from {@code seed}; prints a FAIL line for each failure. */
    static Counts run(long seed, int count, Path repo, Path work, PrintStream report) throws IOException {
        deleteTree(work);
        Path base = work.resolve("base");
        List<String> scenes = prepare(repo, base);
        List<String> own = scenes.stream().filter(n -> n.startsWith("fuzz-")).toList();
        Counts counts = new Counts();
        for (int i = 0; i < count; i++) {
            Random rnd = new Random(mix(seed * 1_000_003L + i));
            Path dir = work.resolve("case" + i);
            copyTree(base, dir);
            // A quarter of the cases start from the fuzz's own scenes, dense in the newer syntaxes.
            String scene = rnd.nextInt(4) == 0 ? own.get(rnd.nextInt(own.size())) : scenes.get(rnd.nextInt(scenes.size()));
            Path scenePath = dir.resolve("scenes").resolve(scene);
            List<String> done = new ArrayList<>();
            int mutations = 1 + (rnd.nextInt(4) == 0 ? rnd.nextInt(3) : 0);
            for (int m = 0; m < mutations; m++) done.add(mutate(rnd, scenePath));
            String what = "case " + i + " (" + scene + ": " + String.join("; ", done) + ")";
            Path out = dir.resolve("out.pfm");
            counts.cases++;
            int rendered = counts.rendered, interrupted = counts.interrupted;
            long t0 = System.nanoTime();
            String failure = check(scenePath, out, counts);
            long ms = (System.nanoTime() - t0) / 1_000_000;
            if (failure != null) {
                counts.failures++;
                report.println("FAIL " + what + ": " + failure);
                if (KEEP != null) {
                    Files.deleteIfExists(out);
                    copyTree(dir, Path.of(KEEP).resolve("case" + i));
                }
            }
            if (VERBOSE) {
                report.println("CASE " + what + " -> " + (failure != null ? "FAIL"
                        : counts.rendered > rendered ? "rendered" : counts.interrupted > interrupted ? "interrupted" : "refused")
                        + " " + ms + " ms");
            }
            deleteTree(dir);
        }
        return counts;
    }

    /**
     * A case's seed, scrambled (SplitMix64's finaliser): java.util.Random's first values for
     * consecutive seeds are nearly equal, which made the first draw of neighbouring cases alike.
     */
    static long mix(long z) {
        z = (z ^ (z >>> 30)) * 0xbf58476d1ce4e5b9L;
        z = (z ^ (z >>> 27)) * 0x94d049bb133111ebL;
        return z ^ (z >>> 31);
    }

    /** Renders one case and returns what broke the promise, or null. */
    private static String check(Path scene, Path out, Counts counts) {
        ByteArrayOutputStream stdout = new ByteArrayOutputStream(), stderr = new ByteArrayOutputStream();
        AtomicReference<Object> result = new AtomicReference<>();
        Thread t = new Thread(() -> {
            try {
                result.set(Main.run(arguments(scene, out),
                        new PrintStream(stdout, true, StandardCharsets.UTF_8), new PrintStream(stderr, true, StandardCharsets.UTF_8)));
            } catch (Throwable e) {
                result.set(e);
            }
        }, "fuzz-case");
        t.start();
        try {
            t.join(TIMEOUT_MS);
            if (t.isAlive()) {
                t.interrupt();
                t.join(TIMEOUT_MS);
                if (t.isAlive()) return "hangs: still running " + 2 * TIMEOUT_MS / 1000 + " s after it started, and after an interrupt";
                counts.interrupted++;
                return Files.exists(out) ? "interrupted after " + TIMEOUT_MS / 1000 + " s, but left " + out.getFileName() : null;
            }
        } catch (InterruptedException e) {
            Thread.currentThread().interrupt();
            return "harness interrupted";
        }
        Object r = result.get();
        String err = stderr.toString(StandardCharsets.UTF_8);
        if (r instanceof Throwable e) return "threw " + e + " " + firstLines(err);
        int status = (Integer) r;
        if (status == 0) {
            counts.rendered++;
            if (!Files.exists(out)) return "exit 0 without an image";
            String bad = nonFinite(out);
            return bad;
        }
        if (status != 2) return "exit " + status + ": " + firstLines(err);
        counts.refused++;
        if (Files.exists(out)) return "exit 2 but the image was written";
        String msg = err.endsWith("\n") ? err.substring(0, err.length() - 1) : err;
        if (msg.isEmpty()) return "exit 2 with nothing on stderr";
        if (msg.indexOf('\n') >= 0) return "exit 2 with " + msg.split("\n", -1).length + " lines: " + firstLines(err);
        if (msg.length() > 400) return "exit 2 with a line of " + msg.length() + " characters: " + msg.substring(0, 200) + "...";
        // A refusal of the scene file as a whole (too large for the heap) has no line: the file is its place.
        boolean wholeScene = msg.startsWith(scene + ": ") && msg.length() > scene.toString().length() + 2;
        if (!LOCATED.matcher(msg).matches() && !wholeScene) return "exit 2 without file:line:column: " + msg;
        return null;
    }

    /**
     * The command line of a case: an animated scene renders one frame, its first as written (so
     * that one image is the promise); if the mutations left no such number, the scene is refused
     * before frames are chosen.
     */
    private static String[] arguments(Path scene, Path out) throws IOException {
        List<String> args = new ArrayList<>(List.of(scene.toString(), "-o", out.toString(), "--quiet", "--threads", "2"));
        String text = Files.readString(scene, StandardCharsets.ISO_8859_1);
        // -0 is frame 0; a negative first frame is refused where it is written, whatever --frame says.
        Matcher first = Pattern.compile("\\banimation\\s*\\{[^}]*?\\bframes\\s+(-?\\d{1,7})(?![\\w.])").matcher(text);
        if (first.find() && Integer.parseInt(first.group(1)) >= 0) args.addAll(List.of("--frame", Integer.toString(Integer.parseInt(first.group(1)))));
        return args.toArray(new String[0]);
    }

    private static String firstLines(String err) {
        String[] lines = err.split("\n");
        StringBuilder s = new StringBuilder("[");
        for (int i = 0; i < Math.min(3, lines.length); i++) {
            String l = lines[i];
            s.append(i > 0 ? " | " : "").append(l.length() > 200 ? l.substring(0, 200) + "..." : l);
        }
        return s.append(lines.length > 3 ? " | ... " + lines.length + " lines]" : "]").toString();
    }

    /** Null if every value of the PFM is finite, else where the first one that is not is. */
    static String nonFinite(Path pfm) {
        try {
            byte[] b = Files.readAllBytes(pfm);
            int pos = 0, newlines = 0;
            while (newlines < 3 && pos < b.length) if (b[pos++] == '\n') newlines++;
            String[] header = new String(b, 0, pos, StandardCharsets.US_ASCII).trim().split("\\s+");
            ByteOrder order = Double.parseDouble(header[3]) < 0 ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
            ByteBuffer data = ByteBuffer.wrap(b, pos, b.length - pos).order(order);
            for (int i = 0; data.remaining() >= 4; i++) {
                float f = data.getFloat();
                if (!Float.isFinite(f)) return "wrote a non-finite value " + f + " at float " + i + " of the PFM";
            }
            return null;
        } catch (IOException | RuntimeException e) {
            return "cannot read back the image: " + e;
        }
    }

    // ---- mutations ----

    private static final String[] NUMBERS = {"NaN", "Infinity", "-Infinity", "1e308", "-1e308", "1e300", "1e38", "1e30", "1e15",
        "-1", "0", "-0", "1e-320", "2147483648", "99999999999999999999999", "65536", "100000000", "12", "-7.5", "0x10", "1e",
        "-2147483649", "9223372036854775808", "4.9e-324", "-1e-320", "1e-300"};
    /** Values at or just past the documented limits of the newer keys (frames, fps, shutter, samples, budgets, targets, levels). */
    private static final String[] EDGES = {"0", "0.0001", "0.01", "0.009", "1", "8", "9", "24", "360", "360.5", "1000", "1000.5",
        "1024", "1025", "65536", "65537", "100000", "100001", "1000000", "1000001", "9999999", "10000000", "16777216", "16777217",
        "1e15", "1e16", "-0.5", "2.5"};
    private static final String[] CONTROLS = {"\0", "\u007f", "\u2028", "\u001b[31m", "\r", "\ufeff", "\u0085"};

    /**
     * Words that stand in for one another: a token of a group is swapped for another of its group
     * (a keyword's sibling, a choice's other value), sometimes for a word of any group.
     */
    private static final String[][] WORDS = {
        {"uniform", "projected", "lazy", "combined"}, {"edge", "object"}, {"linear", "ease", "smooth"}, {"lru", "last-two"},
        {"true", "false"}, {"light", "rectlight", "disclight", "spherelight", "environment"}, {"keys", "turntable", "motion"},
        {"key", "frames", "fps", "shutter"}, {"translate", "rotate", "scale", "pivot"}, {"direction", "speed", "start", "finish"},
        {"subdivmemory", "subdivcache", "subdivtarget", "subdivpolicy", "timesteps", "samples"},
        {"method", "target", "levels", "maxlevel", "level"}, {"sphere", "box", "mesh", "subdiv", "cylinder", "plane", "union", "difference"},
        {"animation", "camera", "settings"}, {"axis", "center", "turns", "normal", "tangent"},
        {"width", "height", "radius", "power", "intensity", "onesided"}, {"catmark", "loop", "bilinear"}, {"x", "y", "z"},
        {"v", "vt", "vn", "f", "t", "mtllib", "usemtl", "g", "o", "s"},
        {"newmtl", "Kd", "Ka", "Ks", "Ns", "d", "Tr", "Tf", "Ni", "Ke", "illum"},
        {"map_Kd", "map_Ks", "map_d", "map_Bump", "bump", "map_Ka"}, {"-s", "-o", "-clamp", "-bm", "-blendu"},
        {"crease", "corner", "hole", "interpolateboundary", "facevaryingpropagatecorners"}};

    /** A number after a key of the newer syntaxes (and of .mtl files): the targeted value mutation. */
    private static final Pattern KEYED_NUMBER = Pattern.compile("(?<![\\w-])(fps|shutter|frames|turns|key|samples|target|maxlevel|level"
            + "|subdivmemory|subdivcache|subdivtarget|timesteps|intensity|power|radius|width|height|speed|start|finish|rotate|scale"
            + "|pivot|axis|center|normal|tangent|Ns|Ni|d|Tr|Kd|Ka|Ks|Ke|Tf|illum|-s|-o|-bm)[ \\t]+(?:[xyz][ \\t]+)?([-+]?\\.?\\d[\\w.+-]*)");

    /** Applies one random mutation to the scene or to one of the files it names; says what it did. */
    private static String mutate(Random rnd, Path scene) throws IOException {
        List<Path> files = referencedFiles(scene);
        if (!files.isEmpty() && rnd.nextInt(5) < 2) {
            Path f = files.get(rnd.nextInt(files.size()));
            String name = scene.getParent().relativize(f).toString();
            String ext = name.substring(name.lastIndexOf('.') + 1).toLowerCase();
            return name + ": " + switch (ext) {
                case "png", "tga" -> mutateImage(rnd, f, ext);
                case "hdr" -> mutateHdr(rnd, f);
                case "pfm" -> mutatePfm(rnd, f);
                default -> mutateText(rnd, f, false);
            };
        }
        return mutateText(rnd, scene, true);
    }

    private static String mutateText(Random rnd, Path file, boolean isScene) throws IOException {
        byte[] bytes = Files.readAllBytes(file);
        String text = new String(bytes, StandardCharsets.UTF_8);
        List<int[]> tokens = new ArrayList<>();
        Matcher m = Pattern.compile("\\S+").matcher(text);
        while (m.find()) tokens.add(new int[] {m.start(), m.end()});
        if (tokens.isEmpty()) return "empty";
        int[] a = tokens.get(rnd.nextInt(tokens.size())), b = tokens.get(rnd.nextInt(tokens.size()));
        String ta = text.substring(a[0], a[1]);
        int op = rnd.nextInt(isScene ? 17 : 13);
        String out, what;
        switch (op) {
            case 0 -> { out = text.substring(0, a[0]) + text.substring(a[1]); what = "deleted '" + shortly(ta) + "' at " + a[0]; }
            case 1 -> { out = text.substring(0, a[1]) + " " + ta + text.substring(a[1]); what = "duplicated '" + shortly(ta) + "' at " + a[0]; }
            case 2 -> {
                int[] x = a[0] < b[0] ? a : b, y = a[0] < b[0] ? b : a;
                if (x == y || x[1] > y[0]) { out = text; what = "no swap"; break; }
                out = text.substring(0, x[0]) + text.substring(y[0], y[1]) + text.substring(x[1], y[0]) + text.substring(x[0], x[1]) + text.substring(y[1]);
                what = "swapped tokens at " + x[0] + " and " + y[0];
            }
            case 3 -> {
                int[] n = numberToken(rnd, text, tokens);
                String v = NUMBERS[rnd.nextInt(NUMBERS.length)];
                if (n == null) { out = text; what = "no number"; break; }
                out = text.substring(0, n[0]) + v + text.substring(n[1]);
                what = "number at " + n[0] + " -> " + v;
            }
            case 4 -> {
                List<int[]> keyed = new ArrayList<>();
                Matcher k = KEYED_NUMBER.matcher(text);
                while (k.find()) keyed.add(new int[] {k.start(2), k.end(2), k.start(1), k.end(1)});
                if (keyed.isEmpty()) { out = text; what = "no keyed number"; break; }
                int[] n = keyed.get(rnd.nextInt(keyed.size()));
                String v = rnd.nextBoolean() ? NUMBERS[rnd.nextInt(NUMBERS.length)] : EDGES[rnd.nextInt(EDGES.length)];
                out = text.substring(0, n[0]) + v + text.substring(n[1]);
                what = "'" + text.substring(n[2], n[3]) + "' value at " + n[0] + " -> " + v;
            }
            case 5 -> {
                int cut = rnd.nextInt(bytes.length + 1);
                Files.write(file, java.util.Arrays.copyOf(bytes, cut));
                return "truncated to " + cut + " bytes";
            }
            case 6 -> {
                int at = rnd.nextInt(bytes.length + 1), n = 1 + rnd.nextInt(16);
                byte[] noise = new byte[n];
                rnd.nextBytes(noise);
                byte[] o = new byte[bytes.length + n];
                System.arraycopy(bytes, 0, o, 0, at);
                System.arraycopy(noise, 0, o, at, n);
                System.arraycopy(bytes, at, o, at + n, bytes.length - at);
                Files.write(file, o);
                return n + " random bytes at " + at;
            }
            case 7 -> {
                String c = CONTROLS[rnd.nextInt(CONTROLS.length)];
                int at = a[0] + rnd.nextInt(a[1] - a[0] + 1);
                out = text.substring(0, at) + c + text.substring(at);
                what = "control character U+" + Integer.toHexString(c.charAt(0)) + " at " + at;
            }
            case 8 -> {
                int len = new int[] {70, 5000, 300_000, 3_000_000}[rnd.nextInt(4)];
                String word = (rnd.nextBoolean() ? "x" : "9").repeat(len);
                out = text.substring(0, a[0]) + word + text.substring(a[1]);
                what = "token at " + a[0] + " -> " + len + " characters";
            }
            case 9 -> {
                // Counts: the first integer of the file (a Workframe header) or a huge level / tag count.
                int[] n = numberToken(rnd, text, tokens);
                if (!isScene && text.startsWith("v ") || !isScene && text.contains("\nf ")) {
                    String tag = rnd.nextBoolean() ? "t hole 100000000/0/0 0\n" : "t crease 1000000000/1/0 0 1 1\n";
                    out = text + "\n" + tag;
                    what = "appended tag '" + tag.trim() + "'";
                } else if (!isScene) {
                    int[] first = tokens.get(0);
                    out = text.substring(0, first[0]) + "100000000" + text.substring(first[1]);
                    what = "first count -> 100000000";
                } else if (n != null) {
                    out = text.substring(0, n[0]) + (1 + rnd.nextInt(12)) + text.substring(n[1]);
                    what = "number at " + n[0] + " -> small integer";
                } else {
                    out = text;
                    what = "no number";
                }
            }
            case 10 -> {
                // A whole line repeated: a statement, a key, a face or a .mtl line many times over.
                int start = text.lastIndexOf('\n', a[0]) + 1, end = text.indexOf('\n', a[0]);
                end = end < 0 ? text.length() : end + 1;
                String line = text.substring(start, end);
                if (!line.endsWith("\n")) line += "\n";
                int times = REPEATS[rnd.nextInt(REPEATS.length)];
                out = text.substring(0, end) + (end == text.length() && !text.endsWith("\n") ? "\n" : "") + line.repeat(times) + text.substring(end);
                what = "line at " + start + " '" + shortly(line.trim()) + "' repeated " + times + " times";
            }
            case 11 -> {
                List<int[]> known = new ArrayList<>();
                List<String[]> groups = new ArrayList<>();
                for (int[] t : tokens) {
                    String w = text.substring(t[0], t[1]);
                    for (String[] g : WORDS) if (List.of(g).contains(w)) { known.add(t); groups.add(g); break; }
                }
                int[] t;
                String[] g;
                if (known.isEmpty()) { t = a; g = WORDS[rnd.nextInt(WORDS.length)]; }
                else { int k = rnd.nextInt(known.size()); t = known.get(k); g = groups.get(k); }
                if (rnd.nextInt(4) == 0) g = WORDS[rnd.nextInt(WORDS.length)];
                String w = g[rnd.nextInt(g.length)];
                out = text.substring(0, t[0]) + w + text.substring(t[1]);
                what = "keyword '" + shortly(text.substring(t[0], t[1])) + "' at " + t[0] + " -> '" + w + "'";
            }
            case 12 -> {
                // The file ends inside a line or a block: cut at a token's end, no partial bytes.
                out = text.substring(0, a[1]);
                what = "cut after '" + shortly(ta) + "' at " + a[1];
            }
            case 13 -> {
                int depth = new int[] {40, 800, 3000, 10000}[rnd.nextInt(4)];
                String[] ops = {"union", "intersection", "difference"};
                StringBuilder s = new StringBuilder(text).append('\n');
                for (int k = 0; k < depth; k++) s.append(ops[rnd.nextInt(3)]).append(" { sphere { center 0 ").append(k % 3).append(" 0 radius 1 } ");
                s.append("box { min -1 -1 -1 max 1 1 1 }");
                for (int k = 0; k < depth; k++) s.append(" }");
                out = s.append('\n').toString();
                what = "appended " + depth + " nested CSG levels";
            }
            case 14 -> {
                String[] huge = {"settings { width 32768 height 16384 }", "settings { width 30000 height 30000 }",
                    "light { position 0 5 0 intensity 1e300 }", "light { position 0 5 0 intensity 1e38 color 1e30 1e30 1e30 }",
                    "sphere { center 1e300 0 0 radius 1e300 }", "sphere { center 0 0 0 radius 1e-300 }",
                    "box { min 0 0 0 max 1 1 1 scale 1e200 }", "box { min 0 0 0 max 1 1 1 scale 1e-200 }",
                    "material m1 { color 1e300 }", "settings { ambient 1e300 }", "settings { background 1e39 }"};
                String h = huge[rnd.nextInt(huge.length)];
                out = text + "\n" + h + "\n";
                what = "appended '" + h + "'";
            }
            default -> {
                String[] r = inject(rnd, text);
                out = r[0];
                what = r[1];
            }
        }
        Files.write(file, out.getBytes(StandardCharsets.UTF_8));
        return what;
    }

    /**
     * Statements of the newer syntaxes, added at the end of a scene: animation, keys of every
     * interpolation, turntables, environments from .hdr and .pfm maps, area lights, adaptive
     * subdivision, OBJ materials, motion. Each is written sensibly; often one of its numbers is then
     * made extreme.
     */
    private static final String[] STATEMENTS = {
        "animation { frames 1 12  fps 24  shutter 180 }",
        "sphere { radius 0.4  translate 1 0 0  keys { interpolation %I  pivot 0 0.5 0  key 1 { translate 0 0 0 }"
            + "  key 6 { translate 0 1 0  rotate 0 90 0  scale 1.5 }  key 12.5 { scale 0.5 0.5 2  rotate 720 0 -30 } } }",
        "union { sphere { radius 0.3 } box { min 0 0 0 max 0.4 0.4 0.4 }  keys { interpolation %I  key 2 { rotate 0 0 0 }  key 3 { rotate 0 180 0 } } }",
        "box { min -0.5 -0.5 -0.5  max 0.5 0.5 0.5  turntable { axis 0 1 0  center 0 0 0  turns 2 } }",
        "environment { file \"%E\"  light true  samples 2  rotate 45  intensity 0.7 }",
        "environment { file \"%E\"  rotate -30  intensity 2 }",
        "rectlight { center 0 4 0  normal 0 -1 0  tangent 1 0 0  width 2  height 1  intensity 3  onesided true  samples 2 }",
        "disclight { center -2 3 -2  normal 1 -1 1  radius 0.5  power 20  samples 1 }",
        "spherelight { center 2 3 -3  radius 0.3  color 1 0.9 0.8  intensity 5  samples 2 }",
        "subdiv { file \"models/cube.dat\"  method %M  target 2  levels %L  maxlevel 6  translate 0 0.5 0 }",
        "subdiv { file \"models/crease-cube.obj\"  method %M  level 3  scale 0.5 }",
        "subdiv { file \"models/obj-materials.obj\"  method %M  target 1  usemtl \"Grid\" { color 0 1 0 }  scale 0.4 }",
        "mesh { file \"models/obj-materials.obj\"  usemtl \"Chrome\" { color 1 0 0 }  scale 0.5  translate -1 0 0 }",
        "sphere { center 0 1 0  radius 0.5  motion { direction 1 0 0  speed 2  start 0.25  finish 0.75 } }",
        "box { min 0 0 0  max 1 1 1  motion { rotate y 90  scale 1.5  pivot 0.5 0.5 0.5  translate 0 1 0 } }",
        "texture fz { image \"%E\"  wrap mirror }  sphere { radius 0.6  material { color 1 1 1  map { texture fz  mapping spherical } } }",
    };
    /** Keys added inside an existing block: the settings' budgets and shutter, a camera's keys or turntable. */
    private static final String[][] KEYS_IN = {
        {"settings", "subdivmemory 8  subdivcache 2  subdivpolicy last-two  subdivtarget 2"},
        {"settings", "subdivmemory 0.5  subdivcache 0.25"},
        {"settings", "shutter 0 0.5  timesteps 1"},
        {"camera", "keys { interpolation %I  key 1 { translate 0 0 0 }  key 4 { translate 1 0.5 0  rotate 0 20 0 }  key 9 { rotate 10 -20 5 } }"},
        {"camera", "turntable { axis 0 1 0.2  center 0 0 0  turns -0.5 }"},
    };
    private static final String[] MAPS = {"../textures/fuzz-sky.pfm", "../textures/fuzz-grey.pfm", "../textures/fuzz-flat.hdr",
        "../textures/sky.hdr", "../textures/dice.png"};

    /** Adds a statement or keys of the newer syntaxes to a scene; returns the text and what was done. */
    private static String[] inject(Random rnd, String text) {
        boolean inBlock = rnd.nextInt(3) == 0;
        String snippet = inBlock ? KEYS_IN[rnd.nextInt(KEYS_IN.length)][1] : STATEMENTS[rnd.nextInt(STATEMENTS.length)];
        String block = inBlock ? null : "";
        if (inBlock) for (String[] k : KEYS_IN) if (k[1].equals(snippet)) block = k[0];
        snippet = snippet.replace("%I", new String[] {"linear", "ease", "smooth"}[rnd.nextInt(3)])
                .replace("%M", new String[] {"projected", "lazy", "combined", "uniform"}[rnd.nextInt(4)])
                .replace("%L", rnd.nextBoolean() ? "edge" : "object")
                .replace("%E", MAPS[rnd.nextInt(MAPS.length)]);
        String extreme = "";
        if (rnd.nextBoolean()) {
            List<int[]> numbers = new ArrayList<>();
            Matcher n = Pattern.compile("(?<![\\w.\"-])-?\\d+(\\.\\d+)?(?![\\w.\"])").matcher(snippet);
            while (n.find()) numbers.add(new int[] {n.start(), n.end()});
            int[] at = numbers.get(rnd.nextInt(numbers.size()));
            String v = rnd.nextBoolean() ? NUMBERS[rnd.nextInt(NUMBERS.length)] : EDGES[rnd.nextInt(EDGES.length)];
            extreme = ", '" + snippet.substring(at[0], at[1]) + "' at " + at[0] + " -> " + v;
            snippet = snippet.substring(0, at[0]) + v + snippet.substring(at[1]);
        }
        // Keys and turntables need an animation: usually there is one.
        boolean animate = snippet.contains("keys {") || snippet.contains("turntable {");
        String prefix = animate && !text.matches("(?s).*\\banimation\\s*\\{.*") && rnd.nextInt(4) != 0
                ? "animation { frames 1 12  fps 24  shutter 180 }\n" : "";
        String out;
        if (inBlock) {
            Matcher open = Pattern.compile("(?m)^\\s*" + block + "\\s*\\{").matcher(text);
            if (open.find()) out = text.substring(0, open.end()) + " " + snippet + " " + text.substring(open.end());
            else out = text + "\n" + block + " { " + (block.equals("camera") ? "eye 0 1 -5  lookat 0 0 0 " : "") + snippet + " }\n";
            out = prefix.isEmpty() ? out : out + "\n" + prefix;
        } else {
            out = text + "\n" + prefix + snippet + "\n";
        }
        return new String[] {out, (inBlock ? "added to " + block + ": '" : "appended '") + shortly(snippet, 200)
                + (prefix.isEmpty() ? "'" : "' with an animation") + extreme};
    }

    /** A random number token (start, end), or null when there is none. */
    private static int[] numberToken(Random rnd, String text, List<int[]> tokens) {
        List<int[]> numbers = new ArrayList<>();
        for (int[] t : tokens) {
            char c = text.charAt(t[0]);
            if (Character.isDigit(c) || (c == '-' || c == '.') && t[1] > t[0] + 1) numbers.add(t);
        }
        return numbers.isEmpty() ? null : numbers.get(rnd.nextInt(numbers.size()));
    }

    private static String mutateImage(Random rnd, Path file, String ext) throws IOException {
        byte[] b = Files.readAllBytes(file);
        switch (rnd.nextInt(4)) {
            case 0 -> {
                int cut = rnd.nextInt(b.length + 1);
                Files.write(file, java.util.Arrays.copyOf(b, cut));
                return "truncated to " + cut + " bytes";
            }
            case 1 -> {
                int n = 1 + rnd.nextInt(8);
                StringBuilder s = new StringBuilder("flipped bytes");
                for (int k = 0; k < n; k++) {
                    int at = rnd.nextInt(Math.min(b.length, 64));
                    b[at] = (byte) rnd.nextInt(256);
                    s.append(' ').append(at);
                }
                Files.write(file, b);
                return s.toString();
            }
            case 2 -> {
                // Dimensions: TGA's are little-endian shorts at 12 and 14, PNG's big-endian ints at 16 and 20.
                int w = new int[] {0, 1, 8192, 16384, 32767, 65535}[rnd.nextInt(6)], h = new int[] {0, 1, 8192, 16384, 65535}[rnd.nextInt(5)];
                if (ext.equals("tga")) {
                    b[12] = (byte) w; b[13] = (byte) (w >> 8); b[14] = (byte) h; b[15] = (byte) (h >> 8);
                } else {
                    ByteBuffer.wrap(b).putInt(16, w).putInt(20, h);
                }
                Files.write(file, b);
                return "dimensions -> " + w + "x" + h;
            }
            default -> {
                byte[] noise = new byte[1 + rnd.nextInt(4096)];
                rnd.nextBytes(noise);
                Files.write(file, noise);
                return "replaced by " + noise.length + " random bytes";
            }
        }
    }

    /** Resolution lines for a Radiance file: sizes at and past the limits, other orientations, junk. */
    private static final String[] HDR_RESOLUTIONS = {"-Y 0 +X 512", "-Y 256 +X 0", "-Y -1 +X 1", "-Y 2147483647 +X 2147483647",
        "-Y 65536 +X 65536", "-Y 1 +X 100000000", "+Y 256 +X 512", "-Y 256 -X 512", "+X 512 -Y 256", "-Y 256 +X 512 9",
        "-Y 1e3 +X 512", "-Y 257 +X 512", "-Y 128 +X 512", "-Y 256 +X 511", "-Y 1 +X 1", "-Y 2 +X 7", "-Y  256  +X  512", "-Y 256 +X"};
    private static final String[] HDR_HEADERS = {"FORMAT=32-bit_rle_xyze", "FORMAT=", "EXPOSURE=NaN", "EXPOSURE=0", "#?RADIANCE",
        "PRIMARIES=0 0 0 0 0 0 0 0", "\0\0\0"};

    /** Radiance .hdr: its header lines and resolution, its run-length rows, its exponents, its size. */
    private static String mutateHdr(Random rnd, Path file) throws IOException {
        byte[] b = Files.readAllBytes(file);
        int headerEnd = indexOf(b, "\n\n".getBytes(StandardCharsets.ISO_8859_1), 0);
        int resEnd = headerEnd < 0 ? -1 : indexOf(b, new byte[] {'\n'}, headerEnd + 2);
        if (resEnd < 0) return mutateImageBytes(rnd, file, b);
        String header = new String(b, 0, headerEnd + 1, StandardCharsets.ISO_8859_1);
        String res = new String(b, headerEnd + 2, resEnd - headerEnd - 2, StandardCharsets.ISO_8859_1);
        byte[] data = java.util.Arrays.copyOfRange(b, resEnd + 1, b.length);
        switch (rnd.nextInt(7)) {
            case 0 -> {
                String r = HDR_RESOLUTIONS[rnd.nextInt(HDR_RESOLUTIONS.length)];
                write(file, header + "\n" + r + "\n", data);
                return "resolution '" + res + "' -> '" + r + "'";
            }
            case 1 -> {
                String[] lines = header.split("\n", -1);
                int at = 1 + rnd.nextInt(Math.max(1, lines.length - 1));
                String h = switch (rnd.nextInt(4)) {
                    case 0 -> HDR_HEADERS[rnd.nextInt(HDR_HEADERS.length)];
                    case 1 -> "X".repeat(5000);
                    case 2 -> ("EXPOSURE=1\n").repeat(2000).trim();
                    default -> rnd.nextBoolean() ? "#?RGBE" : "#?RADIANCE ";
                };
                List<String> l = new ArrayList<>(List.of(lines));
                if (h.startsWith("#?")) l.set(0, h);
                else l.add(at, h);
                write(file, String.join("\n", l) + "\n" + res + "\n", data);
                return "header line " + (h.startsWith("#?") ? "1" : at + 1) + " -> '" + shortly(h) + "'";
            }
            case 2 -> {
                // A run-length row's counts: a literal of 0, a run or literal past the row's end, a width that differs.
                int at = Math.min(data.length - 1, 4 + rnd.nextInt(Math.max(1, Math.min(data.length - 4, 4096))));
                int v = new int[] {0, 128, 129, 255, 127, 2}[rnd.nextInt(6)];
                if (rnd.nextInt(3) == 0 && data.length > 4) { at = 2 + rnd.nextInt(2); v = rnd.nextInt(256); }
                data[at] = (byte) v;
                write(file, header + "\n" + res + "\n", data);
                return "data byte " + at + " -> " + v;
            }
            case 3 -> {
                // Flat rows of one pattern at the header's size: the brightest values, the darkest, black, one sun texel.
                int[] wh = hdrSize(res);
                if (wh == null || (long) wh[0] * wh[1] > 1 << 20) return mutateImageBytes(rnd, file, b);
                String kind = new String[] {"max", "tiny", "black", "sun", "random"}[rnd.nextInt(5)];
                write(file, header + "\n" + res + "\n", flatRgbe(rnd, wh[0], wh[1], kind));
                return "pixels -> flat " + kind;
            }
            case 4 -> {
                int[][] sizes = {{1, 1}, {1, 2}, {2, 1}, {3, 1}, {8, 1}, {1, 1000}, {4096, 1}, {9, 5}};
                int[] wh = sizes[rnd.nextInt(sizes.length)];
                String kind = new String[] {"max", "tiny", "black", "sun", "random"}[rnd.nextInt(5)];
                write(file, "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y " + wh[1] + " +X " + wh[0] + "\n", flatRgbe(rnd, wh[0], wh[1], kind));
                return "replaced by a flat " + wh[0] + "x" + wh[1] + " " + kind + " image";
            }
            default -> { return mutateImageBytes(rnd, file, b); }
        }
    }

    private static int[] hdrSize(String res) {
        String[] f = res.trim().split("\\s+");
        try {
            return new int[] {Integer.parseInt(f[3]), Integer.parseInt(f[1])};
        } catch (RuntimeException e) {
            return null;
        }
    }

    /** Flat RGBE pixels (four bytes each; the first two never 2 2 and never 1 1 1, so no row reads as run-length). */
    private static byte[] flatRgbe(Random rnd, int w, int h, String kind) {
        byte[] p = new byte[4 * w * h];
        for (int i = 0; i < w * h; i++) {
            int r, g, bl, e;
            switch (kind) {
                case "max" -> { r = g = bl = 255; e = 255; }
                case "tiny" -> { r = g = bl = 3; e = 1; }
                case "black" -> { r = g = bl = 0; e = 0; }
                case "sun" -> { boolean sun = i == w * h / 3; r = g = bl = sun ? 255 : 0; e = sun ? 255 : 0; }
                default -> { r = 3 + rnd.nextInt(250); g = rnd.nextInt(256); bl = rnd.nextInt(256); e = rnd.nextInt(256); }
            }
            p[4 * i] = (byte) r; p[4 * i + 1] = (byte) g; p[4 * i + 2] = (byte) bl; p[4 * i + 3] = (byte) e;
        }
        return p;
    }

    private static final String[] PFM_TYPES = {"PF", "Pf", "P6", "pf", "PF4", ""};
    private static final String[] PFM_SIZES = {"0", "-1", "1", "2147483647", "65536", "1e3", "16777217", "3"};
    private static final String[] PFM_SCALES = {"0", "-0", "NaN", "1e308", "-1e-320", "-Infinity", "1", "-1", "x", "-1e400"};
    private static final float[] PFM_VALUES = {Float.NaN, Float.POSITIVE_INFINITY, Float.NEGATIVE_INFINITY, -0f, -1f, Float.MAX_VALUE,
        Float.MIN_VALUE, 1e-40f, 1e38f, 100f, 1e30f, 0f};

    /** PFM: its header (type, size, scale and byte order), its floats (NaN, infinities, negatives, denormals, the largest), its size. */
    private static String mutatePfm(Random rnd, Path file) throws IOException {
        byte[] b = Files.readAllBytes(file);
        int pos = 0, newlines = 0;
        while (newlines < 3 && pos < b.length) if (b[pos++] == '\n') newlines++;
        String[] h = new String(b, 0, pos, StandardCharsets.ISO_8859_1).trim().split("\\s+");
        if (newlines < 3 || h.length != 4) return mutateImageBytes(rnd, file, b);
        byte[] data = java.util.Arrays.copyOfRange(b, pos, b.length);
        switch (rnd.nextInt(6)) {
            case 0 -> {
                int which = rnd.nextInt(4);
                String[] choices = which == 0 ? PFM_TYPES : which == 3 ? PFM_SCALES : PFM_SIZES;
                String was = h[which];
                h[which] = choices[rnd.nextInt(choices.length)];
                write(file, h[0] + "\n" + h[1] + " " + h[2] + "\n" + h[3] + "\n", data);
                return "header '" + was + "' -> '" + h[which] + "'";
            }
            case 1, 2 -> {
                ByteOrder order = h[3].startsWith("-") ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN;
                ByteBuffer f = ByteBuffer.wrap(data).order(order);
                float v = PFM_VALUES[rnd.nextInt(PFM_VALUES.length)];
                boolean all = rnd.nextInt(3) == 0;
                int at = rnd.nextInt(Math.max(1, data.length / 4));
                for (int i = 0; i + 4 <= data.length; i += 4) if (all || i == 4 * at) f.putFloat(i, v);
                write(file, new String(b, 0, pos, StandardCharsets.ISO_8859_1), data);
                return (all ? "every value" : "value " + at) + " -> " + v;
            }
            case 3 -> {
                int[][] sizes = {{1, 1}, {1, 2}, {2, 1}, {1, 4096}, {5, 3}};
                int[] wh = sizes[rnd.nextInt(sizes.length)];
                boolean grey = rnd.nextBoolean(), little = rnd.nextBoolean();
                float v = PFM_VALUES[rnd.nextInt(PFM_VALUES.length)];
                String kind = new String[] {"uniform", "one texel", "random"}[rnd.nextInt(3)];
                int n = wh[0] * wh[1] * (grey ? 1 : 3);
                ByteBuffer f = ByteBuffer.allocate(4 * n).order(little ? ByteOrder.LITTLE_ENDIAN : ByteOrder.BIG_ENDIAN);
                for (int i = 0; i < n; i++) {
                    f.putFloat(switch (kind) {
                        case "uniform" -> v;
                        case "one texel" -> i == n / 2 ? v : 0f;
                        default -> rnd.nextFloat() * 2;
                    });
                }
                write(file, (grey ? "Pf" : "PF") + "\n" + wh[0] + " " + wh[1] + "\n" + (little ? "-1.0" : "1.0") + "\n", f.array());
                return "replaced by a " + (grey ? "grey " : "colour ") + wh[0] + "x" + wh[1] + (little ? " little" : " big") + "-endian "
                        + kind + (kind.equals("random") ? "" : " " + v) + " image";
            }
            default -> { return mutateImageBytes(rnd, file, b); }
        }
    }

    /** Format-blind byte mutations of an image: truncation, flipped bytes near the start or anywhere, noise. */
    private static String mutateImageBytes(Random rnd, Path file, byte[] b) throws IOException {
        switch (rnd.nextInt(3)) {
            case 0 -> {
                int cut = rnd.nextInt(b.length + 1);
                Files.write(file, java.util.Arrays.copyOf(b, cut));
                return "truncated to " + cut + " bytes";
            }
            case 1 -> {
                int n = 1 + rnd.nextInt(8);
                boolean early = rnd.nextBoolean();
                StringBuilder s = new StringBuilder("flipped bytes");
                for (int k = 0; k < n && b.length > 0; k++) {
                    int at = rnd.nextInt(early ? Math.min(b.length, 64) : b.length);
                    b[at] = (byte) rnd.nextInt(256);
                    s.append(' ').append(at);
                }
                Files.write(file, b);
                return s.toString();
            }
            default -> {
                byte[] noise = new byte[1 + rnd.nextInt(4096)];
                rnd.nextBytes(noise);
                Files.write(file, noise);
                return "replaced by " + noise.length + " random bytes";
            }
        }
    }

    private static void write(Path file, String head, byte[] data) throws IOException {
        byte[] h = head.getBytes(StandardCharsets.ISO_8859_1);
        byte[] o = java.util.Arrays.copyOf(h, h.length + data.length);
        System.arraycopy(data, 0, o, h.length, data.length);
        Files.write(file, o);
    }

    private static int indexOf(byte[] b, byte[] what, int from) {
        outer:
        for (int i = from; i + what.length <= b.length; i++) {
            for (int k = 0; k < what.length; k++) if (b[i + k] != what[k]) continue outer;
            return i;
        }
        return -1;
    }

    /**
     * The files a scene names in double quotes that exist beside it, and the files those name in
     * turn: an OBJ file's {@code mtllib} libraries and a library's {@code map_} and {@code bump} images.
     */
    private static List<Path> referencedFiles(Path scene) throws IOException {
        List<Path> out = new ArrayList<>();
        String text = new String(Files.readAllBytes(scene), StandardCharsets.UTF_8);
        Matcher m = Pattern.compile("\"([^\"\\n]{1,200})\"").matcher(text);
        while (m.find()) add(out, scene.getParent(), m.group(1));
        for (int i = 0; i < out.size(); i++) {
            Path f = out.get(i);
            String n = f.getFileName().toString().toLowerCase();
            if (!n.endsWith(".obj") && !n.endsWith(".mtl")) continue;
            for (String line : new String(Files.readAllBytes(f), StandardCharsets.UTF_8).split("\n")) {
                String[] w = line.trim().split("\\s+");
                String k = w[0].toLowerCase();
                if (k.equals("mtllib")) for (int j = 1; j < w.length; j++) add(out, f.getParent(), w[j]);
                else if ((k.startsWith("map_") || k.equals("bump")) && w.length > 1) add(out, f.getParent(), w[w.length - 1]);
            }
        }
        return out;
    }

    private static void add(List<Path> out, Path dir, String name) {
        try {
            Path p = dir.resolve(name).normalize();
            if (Files.isRegularFile(p) && !out.contains(p)) out.add(p);
        } catch (RuntimeException e) {
            // not a path
        }
    }

    // ---- the copied scenes ----

    /**
     * Scenes of the fuzz's own, beside the copies of scenes/: each writes many of the newer
     * syntaxes densely, so that token mutations land in them often. They render unmutated.
     */
    private static final String[][] OWN_SCENES = {
        {"fuzz-animation.dat", """
            settings { width 12 height 9 samples 2 background 0.2 0.3 0.4 }
            animation { frames 1 12  fps 24  shutter 180 }
            camera { eye 0 2 -7  lookat 0 0.5 0  fov 40
                     keys { interpolation smooth  key 1 { translate 0 0 0 }  key 6 { translate 1 0.5 0  rotate 0 15 0 }  key 12 { rotate 5 -10 0 } } }
            light { position -5 8 -6  intensity 0.9 }
            material red { color 0.8 0.2 0.1 }
            plane { normal 0 1 0  offset -1 }
            sphere { radius 0.5  material red  translate -1.5 0 0
                     keys { interpolation linear  pivot 0 0.5 0  key 1 { translate 0 0 0 }  key 4.5 { translate 0 1 0  scale 1.2 }  key 12 { rotate 0 90 0  scale 0.5 1 2 } } }
            union { box { min -0.4 -0.4 -0.4  max 0.4 0.4 0.4 }  sphere { center 0.4 0.4 0  radius 0.3 }
                    keys { interpolation ease  key 2 { rotate 0 0 0 }  key 10 { rotate 0 270 0  translate 0 0.5 0 } } }
            box { min -0.3 -1 -0.3  max 0.3 -0.4 0.3  translate 1.6 0 0  turntable { axis 0 1 0  center 1.6 0 0  turns -2 } }
            subdiv { file "models/crease-cube.obj"  level 2  scale 0.4  translate 0 0 1.5
                     keys { interpolation smooth  key 1 { scale 1 }  key 12 { scale 2  rotate 0 0 45 } }  motion { translate 0 0.2 0 } }
            """},
        {"fuzz-lights.dat", """
            settings { width 12 height 9 samples 1 ambient 0.05 }
            camera { eye 0 2 -7  lookat 0 0.5 0  fov 45 }
            environment { file "../textures/fuzz-sky.pfm"  rotate 30  intensity 0.8  light true  samples 2 }
            rectlight { center 0 4 0  normal 0 -1 0  tangent 1 0 1  width 2  height 1  intensity 3  onesided true  samples 2 }
            disclight { center -3 3 -2  normal 1 -1 1  radius 0.5  power 30  samples 1 }
            spherelight { center 3 3 -3  radius 0.3  color 1 0.9 0.8  intensity 5  samples 2 }
            texture grey { image "../textures/fuzz-grey.pfm" }
            texture flat { image "../textures/fuzz-flat.hdr"  wrap clamp }
            plane { normal 0 1 0  offset -1  material { color 0.6 0.6 0.6  map { texture flat  mapping planar } } }
            sphere { center -1.5 0 0  radius 0.8  material { color 1 1 1  map { texture grey  mapping spherical } } }
            mesh { file "models/obj-materials.obj"  scale 0.6  translate 1.5 0 0  usemtl "Chrome" { color 0.2 0.3 0.9 } }
            sphere { center 0 0 1  radius 0.5  motion { direction 1 0 0  speed 2  start 0.25  finish 0.75 } }
            """},
        {"fuzz-adaptive.dat", """
            settings { width 12 height 9 samples 1  subdivmemory 8  subdivcache 2  subdivpolicy lru  shutter 0 1  timesteps 1 }
            camera { eye 0 2 -7  lookat 0 0.5 0  fov 45 }
            light { position -5 8 -6 }
            subdiv { file "models/cube.dat"  method projected  target 2  levels object  maxlevel 6  translate -2 0 0 }
            subdiv { file "models/crease-cube.obj"  method lazy  level 3  scale 0.7 }
            subdiv { file "models/obj-materials.obj"  method combined  target 1  levels edge  translate 2 0 0  usemtl "Paint" { color 0 0.8 0 } }
            subdiv { file "models/loop_icosahedron.obj"  scheme loop  method lazy  target 4  translate 0 0 2
                     motion { rotate y 40  pivot 0 0 2 } }
            """},
    };

    /** Copies scenes/ (without bench), its models and textures/ into {@code base}, each scene made small, and the fuzz's own scenes and maps; returns the scene names. */
    private static List<String> prepare(Path repo, Path base) throws IOException {
        copyTree(repo.resolve("scenes").resolve("models"), base.resolve("scenes").resolve("models"));
        copyTree(repo.resolve("textures"), base.resolve("textures"));
        writeMaps(base.resolve("textures"));
        List<String> names = new ArrayList<>();
        try (Stream<Path> s = Files.list(repo.resolve("scenes"))) {
            for (Path p : s.sorted().toList()) {
                String n = p.getFileName().toString();
                if (!n.endsWith(".dat") || !Files.isRegularFile(p)) continue;
                String text = Files.readString(p);
                Matcher steps = Pattern.compile("\\btimesteps\\s+(\\d+)").matcher(text);
                String samples = steps.find() ? steps.group(1) : "1";
                // Only the settings' size and samples: an area light's width and samples stay as written.
                Matcher settings = Pattern.compile("(?m)^settings\\s*\\{[^}]*\\}").matcher(text);
                if (settings.find()) {
                    String small = settings.group().replaceAll("\\bwidth\\s+\\d+", "width 12").replaceAll("\\bheight\\s+\\d+", "height 9")
                            .replaceAll("\\bsamples\\s+\\d+", "samples " + samples);
                    text = text.substring(0, settings.start()) + small + text.substring(settings.end());
                }
                Files.writeString(base.resolve("scenes").resolve(n), text);
                names.add(n);
            }
        }
        for (String[] own : OWN_SCENES) {
            Files.writeString(base.resolve("scenes").resolve(own[0]), own[1]);
            names.add(own[0]);
        }
        return names;
    }

    /** Small maps in the formats no file of textures/ has: a colour PFM (little-endian), a grey one (big-endian), a flat (not run-length) Radiance file. */
    private static void writeMaps(Path textures) throws IOException {
        int w = 32, h = 16;
        ByteBuffer sky = ByteBuffer.allocate(4 * 3 * w * h).order(ByteOrder.LITTLE_ENDIAN);
        for (int y = 0; y < h; y++) {
            for (int x = 0; x < w; x++) {
                boolean sun = y == 10 && x == 20;  // rows run bottom-up: a sun above the horizon
                float up = y / (float) h;
                sky.putFloat(sun ? 50 : 0.2f + 0.5f * up).putFloat(sun ? 45 : 0.3f + 0.5f * up).putFloat(sun ? 40 : 0.4f + 0.6f * up);
            }
        }
        write(textures.resolve("fuzz-sky.pfm"), "PF\n" + w + " " + h + "\n-1.0\n", sky.array());
        ByteBuffer grey = ByteBuffer.allocate(4 * 8 * 4).order(ByteOrder.BIG_ENDIAN);
        for (int i = 0; i < 32; i++) grey.putFloat((i * 7 % 32) / 31f);
        write(textures.resolve("fuzz-grey.pfm"), "Pf\n8 4\n1.0\n", grey.array());
        write(textures.resolve("fuzz-flat.hdr"), "#?RADIANCE\nFORMAT=32-bit_rle_rgbe\n\n-Y 8 +X 16\n", flatRgbe(new Random(1), 16, 8, "random"));
    }

    private static void copyTree(Path from, Path to) throws IOException {
        try (Stream<Path> s = Files.walk(from)) {
            for (Path p : s.toList()) {
                Path q = to.resolve(from.relativize(p).toString());
                if (Files.isDirectory(p)) Files.createDirectories(q);
                else Files.copy(p, q);
            }
        }
    }

    private static void deleteTree(Path dir) throws IOException {
        if (!Files.exists(dir)) return;
        try (Stream<Path> s = Files.walk(dir)) {
            for (Path p : s.sorted(Comparator.reverseOrder()).toList()) Files.deleteIfExists(p);
        }
    }

    private static String shortly(String s) {
        return shortly(s, 30);
    }

    private static String shortly(String s, int n) {
        s = s.replace("\n", "\\n");
        return s.length() > n ? s.substring(0, n) + "..." : s;
    }
}
