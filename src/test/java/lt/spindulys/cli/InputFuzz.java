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
 * {@code render DIR/caseN/scenes/SCENE -o out.pfm}.
 */
public final class InputFuzz {
    private InputFuzz() {}

    /** A render that takes longer than this is interrupted: a slow valid scene is not a failure, a hang shows as one. */
    static final long TIMEOUT_MS = 8000;

    private static final boolean VERBOSE = Boolean.getBoolean("fuzz.verbose");
    private static final String KEEP = System.getProperty("fuzz.keep");

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
        Counts counts = new Counts();
        for (int i = 0; i < count; i++) {
            Random rnd = new Random(seed * 1_000_003L + i);
            Path dir = work.resolve("case" + i);
            copyTree(base, dir);
            String scene = scenes.get(rnd.nextInt(scenes.size()));
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
        if (!LOCATED.matcher(msg).matches()) return "exit 2 without file:line:column: " + msg;
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
        Matcher first = Pattern.compile("\\banimation\\s*\\{[^}]*?\\bframes\\s+(\\d{1,7})(?![\\w.])").matcher(text);
        if (first.find()) args.addAll(List.of("--frame", first.group(1)));
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
        "-1", "0", "-0", "1e-320", "2147483648", "99999999999999999999999", "65536", "100000000", "12", "-7.5", "0x10", "1e"};
    private static final String[] CONTROLS = {"\0", "\u007f", "\u2028", "\u001b[31m", "\r", "\ufeff", "\u0085"};

    /** Applies one random mutation to the scene or to one of the files it names; says what it did. */
    private static String mutate(Random rnd, Path scene) throws IOException {
        List<Path> files = referencedFiles(scene);
        if (!files.isEmpty() && rnd.nextInt(5) < 2) {
            Path f = files.get(rnd.nextInt(files.size()));
            String name = scene.getParent().relativize(f).toString();
            String ext = name.substring(name.lastIndexOf('.') + 1).toLowerCase();
            if (ext.equals("png") || ext.equals("tga")) return name + ": " + mutateImage(rnd, f, ext);
            return name + ": " + mutateText(rnd, f, false);
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
        int op = rnd.nextInt(isScene ? 12 : 10);
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
            case 3, 4 -> {
                int[] n = numberToken(rnd, text, tokens);
                String v = NUMBERS[rnd.nextInt(NUMBERS.length)];
                if (n == null) { out = text; what = "no number"; break; }
                out = text.substring(0, n[0]) + v + text.substring(n[1]);
                what = "number at " + n[0] + " -> " + v;
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
                int depth = new int[] {40, 800, 3000, 10000}[rnd.nextInt(4)];
                String[] ops = {"union", "intersection", "difference"};
                StringBuilder s = new StringBuilder(text).append('\n');
                for (int k = 0; k < depth; k++) s.append(ops[rnd.nextInt(3)]).append(" { sphere { center 0 ").append(k % 3).append(" 0 radius 1 } ");
                s.append("box { min -1 -1 -1 max 1 1 1 }");
                for (int k = 0; k < depth; k++) s.append(" }");
                out = s.append('\n').toString();
                what = "appended " + depth + " nested CSG levels";
            }
            default -> {
                String[] huge = {"settings { width 32768 height 16384 }", "settings { width 30000 height 30000 }",
                    "light { position 0 5 0 intensity 1e300 }", "light { position 0 5 0 intensity 1e38 color 1e30 1e30 1e30 }",
                    "sphere { center 1e300 0 0 radius 1e300 }", "sphere { center 0 0 0 radius 1e-300 }",
                    "box { min 0 0 0 max 1 1 1 scale 1e200 }", "box { min 0 0 0 max 1 1 1 scale 1e-200 }",
                    "material m1 { color 1e300 }", "settings { ambient 1e300 }", "settings { background 1e39 }"};
                String h = huge[rnd.nextInt(huge.length)];
                out = text + "\n" + h + "\n";
                what = "appended '" + h + "'";
            }
        }
        Files.write(file, out.getBytes(StandardCharsets.UTF_8));
        return what;
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

    /** The files a scene names in double quotes that exist beside it. */
    private static List<Path> referencedFiles(Path scene) throws IOException {
        List<Path> out = new ArrayList<>();
        String text = new String(Files.readAllBytes(scene), StandardCharsets.UTF_8);
        Matcher m = Pattern.compile("\"([^\"\\n]{1,200})\"").matcher(text);
        while (m.find()) {
            try {
                Path p = scene.getParent().resolve(m.group(1)).normalize();
                if (Files.isRegularFile(p) && !out.contains(p)) out.add(p);
            } catch (RuntimeException e) {
                // not a path
            }
        }
        return out;
    }

    // ---- the copied scenes ----

    /** Copies scenes/ (without bench), its models and textures/ into {@code base}, each scene made small; returns the scene names. */
    private static List<String> prepare(Path repo, Path base) throws IOException {
        copyTree(repo.resolve("scenes").resolve("models"), base.resolve("scenes").resolve("models"));
        copyTree(repo.resolve("textures"), base.resolve("textures"));
        List<String> names = new ArrayList<>();
        try (Stream<Path> s = Files.list(repo.resolve("scenes"))) {
            for (Path p : s.sorted().toList()) {
                String n = p.getFileName().toString();
                if (!n.endsWith(".dat") || !Files.isRegularFile(p)) continue;
                String text = Files.readString(p);
                Matcher steps = Pattern.compile("\\btimesteps\\s+(\\d+)").matcher(text);
                String samples = steps.find() ? steps.group(1) : "1";
                text = text.replaceAll("\\bwidth\\s+\\d+", "width 12").replaceAll("\\bheight\\s+\\d+", "height 9")
                        .replaceAll("\\bsamples\\s+\\d+", "samples " + samples);
                Files.writeString(base.resolve("scenes").resolve(n), text);
                names.add(n);
            }
        }
        return names;
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
        return s.length() > 30 ? s.substring(0, 30) + "..." : s;
    }
}
