package lt.spindulys.subdiv;

import java.io.IOException;
import java.io.InputStream;
import java.io.UncheckedIOException;
import java.net.URISyntaxException;
import java.net.URL;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;
import java.util.TreeMap;
import java.util.concurrent.ConcurrentHashMap;
import java.util.regex.Matcher;
import java.util.regex.Pattern;
import java.util.stream.Stream;
import java.util.zip.GZIPInputStream;

import lt.spindulys.io.ObjReader;
import lt.spindulys.mesh.MeshData;

/**
 * The OpenSubdiv regression shapes and Far's refinements of them, gzipped under
 * {@code src/test/resources/subdiv/} (see the README there): loading a shape into a
 * {@link ControlMesh} and reading the reference files.
 */
final class Corpus {
    private Corpus() {}

    static final String DIR = "subdiv";

    /** One reference file: its sections of numbers, by name. */
    record Oracle(String name, int level, Map<String, double[][]> sections) {
        double[][] section(String s) { return sections.get(s); }
    }

    private static final Map<String, String> TEXT = new ConcurrentHashMap<>();
    private static final Map<String, Oracle> ORACLES = new ConcurrentHashMap<>();

    static Path dir() {
        URL url = Corpus.class.getClassLoader().getResource(DIR + "/OPENSUBDIV-LICENSE.txt");
        if (url == null) throw new IllegalStateException("test resources " + DIR + "/ not on the class path");
        try {
            return Path.of(url.toURI()).getParent();
        } catch (URISyntaxException e) {
            throw new IllegalStateException(e);
        }
    }

    /** Shape name (without .obj) to the levels it has reference files for, in name order. */
    static Map<String, List<Integer>> shapes() {
        Map<String, List<Integer>> out = new TreeMap<>();
        Pattern p = Pattern.compile("((?:catmark|loop|bilinear)_\\w+)\\.L(\\d)\\.txt\\.gz");
        try (Stream<Path> files = Files.list(dir())) {
            for (Path f : (Iterable<Path>) files::iterator) {
                Matcher m = p.matcher(f.getFileName().toString());
                if (m.matches()) out.computeIfAbsent(m.group(1), k -> new ArrayList<>()).add(Integer.parseInt(m.group(2)));
            }
        } catch (IOException e) {
            throw new UncheckedIOException(e);
        }
        out.values().forEach(l -> l.sort(null));
        return out;
    }

    static String text(String file) {
        return TEXT.computeIfAbsent(file, f -> {
            try (InputStream in = new GZIPInputStream(Files.newInputStream(dir().resolve(f + ".gz")))) {
                return new String(in.readAllBytes(), StandardCharsets.US_ASCII);
            } catch (IOException e) {
                throw new UncheckedIOException(e);
            }
        });
    }

    /** The shape as a control mesh, read with its tags by the project's OBJ reader. */
    static ControlMesh load(String shape) {
        return load(shape, o -> o);
    }

    /** The shape with its options (after its tags) changed by {@code options}. */
    static ControlMesh load(String shape, java.util.function.UnaryOperator<SubdivOptions> options) {
        SubdivInput in = ObjReader.parseSubdiv(text(shape + ".obj"), shape + ".obj");
        return in.withOptions(options.apply(in.options().withScheme(scheme(shape)))).toControlMesh();
    }

    /** The scheme a shape is refined with in the reference data: its name's prefix says it. */
    static SubdivOptions.Scheme scheme(String shape) {
        if (shape.startsWith("loop_")) return SubdivOptions.Scheme.LOOP;
        if (shape.startsWith("bilinear_")) return SubdivOptions.Scheme.BILINEAR;
        return SubdivOptions.Scheme.CATMARK;
    }

    static Oracle oracle(String shape, int level) {
        String file = shape + ".L" + level + ".txt";
        return ORACLES.computeIfAbsent(file, f -> parse(f, level));
    }

    /** A reference file by its name (without .gz) under the corpus directory. */
    static Oracle oracle(String file, int level, boolean cached) {
        return cached ? ORACLES.computeIfAbsent(file, f -> parse(f, level)) : parse(file, level);
    }

    private static Oracle parse(String file, int level) {
        Map<String, double[][]> sections = new LinkedHashMap<>();
        String[] lines = text(file).split("\n");
        int i = 0;
        boolean ended = false;
        while (i < lines.length) {
            String line = lines[i++].trim();
            if (line.isEmpty() || line.startsWith("#")) continue;
            String[] tok = line.split("\\s+");
            if (!Character.isLetter(tok[0].charAt(0))) throw new IllegalStateException(file + ": data line outside a section: " + line);
            int count = Integer.parseInt(tok[1]);
            double[][] rows = new double[count][];
            for (int r = 0; r < count; r++) {
                String[] t = lines[i++].trim().split("\\s+");
                double[] row = new double[t.length];
                for (int k = 0; k < t.length; k++) row[k] = Double.parseDouble(t[k]);
                rows[r] = row;
            }
            sections.put(tok[0], rows);
            if (tok[0].equals("end")) ended = true;
        }
        if (!ended) throw new IllegalStateException(file + " is truncated (no end section)");
        return new Oracle(file, level, sections);
    }
}
