package lt.spindulys.io;

import java.io.IOException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.regex.Pattern;

import lt.spindulys.limits.HeapBudget;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.limits.MessageText;
import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;

/**
 * Reads the two files of the thesis's modeller (Workframe): a {@code .dat} polygon mesh and a
 * {@code .tex} unwrap. Both are line based: blank lines and {@code #} comments are skipped, and
 * every other line holds whitespace-separated numbers. An unwrap comes in two forms, told apart by
 * its header: the thesis's, texture points with faces of their own (the face-varying data of
 * OpenSubdiv), or one texture point per face corner.
 *
 * <pre>
 * mesh (.dat):  point_count face_count       unwrap (.tex):  point_count face_count   or  corner_count
 *               x y z   (point_count lines)                  u v [w]  (point_count)       u v  (corner_count lines,
 *               n i0 i1 ... i(n-1)  (face_count lines, 0-based)  n t0 ... t(n-1) (face_count)   face after face)
 * </pre>
 *
 * The full description is in docs/mesh-formats.md. Errors are {@link SceneException}s naming
 * file:line:column of the offending number (or of the end of the file when lines are missing).
 */
public final class WorkframeReader {
    private WorkframeReader() {}

    /** The shortest lines, with their line break: "0 0 0", "3 0 1 2" and "0 0". */
    private static final int MIN_POINT_LINE = 6, MIN_FACE_LINE = 8, MIN_CORNER_LINE = 4;

    private static final Pattern INTEGER = Pattern.compile("[+-]?[0-9]+");
    private static final Pattern NUMBER = Pattern.compile("[+-]?([0-9]+\\.?[0-9]*|\\.[0-9]+)([eE][+-]?[0-9]+)?");

    /**
     * Reads a {@code .dat} mesh file.
     *
     * @param file the file
     * @return the mesh
     * @throws IOException if the file cannot be read
     */
    public static MeshData readMesh(Path file) throws IOException {
        return parseMesh(readText(file, "mesh"), file.toString());
    }

    /**
     * Parses {@code .dat} mesh text; {@code fileName} names it in messages and is the mesh's source.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @return the mesh
     */
    public static MeshData parseMesh(String text, String fileName) {
        Lines in = new Lines(text, fileName);
        Line header = in.next();
        if (header == null) throw in.errorAtEnd("empty mesh file: expected the header 'point_count face_count'");
        if (header.size() != 2) {
            throw in.error(header.size() > 2 ? header.at(2) : header.end(),
                    "expected the header 'point_count face_count' (two integers), found " + header.describe());
        }
        int points = in.count(header, 0, "point count", 3);
        int faces = in.count(header, 1, "face count", 1);
        // A header that announces more lines than the rest of the file has room for is wrong, and
        // is said to be so here, before anything is allocated for it (each line is at least a
        // number and a line break). Smaller overstatements are found where the lines run out.
        long rest = in.remaining(), room = (rest + 1) / 2;
        if (points > room || (long) points + faces > room) {
            throw in.error(header.at(points > room ? 0 : 1), "the header announces " + plural(points, "point") + " and " + plural(faces, "face")
                    + ", but the rest of the file (" + plural(rest, "character") + ") has room for at most " + plural(room, "line"));
        }
        // The arrays are sized by what the rest of the file can hold ('0 0 0' and '3 0 1 2' with a
        // line break), so whatever the header says they cost at most a few bytes per character.
        int pointRoom = (int) Math.min(points, (rest + 1) / MIN_POINT_LINE);
        int faceRoom = (int) Math.min(faces, (rest + 1) / MIN_FACE_LINE);
        try {
            HeapBudget.require(HeapBudget.sum(HeapBudget.product(pointRoom, 3 * 8), HeapBudget.product(faceRoom, 4)),
                    "the mesh's " + plural(points, "point") + " and " + plural(faces, "face"));
        } catch (IllegalArgumentException e) {
            throw in.error(header.at(0), e.getMessage());
        }

        double[] positions = new double[3 * pointRoom];
        for (int i = 0; i < points; i++) {
            if (3 * i == positions.length) positions = Arrays.copyOf(positions, 3 * (int) Math.min(points, 2L * i + 16));
            Line l = in.next();
            if (l == null) throw in.errorAtEnd("the file ends after " + i + " of the " + points + " points the header announces (at " + header.position(0) + ")");
            if (l.size() != 3) {
                String what = "point " + i + " has " + plural(l.size(), "number") + ", expected 3 (x y z)";
                if (i > 0 && looksLikeFace(l)) {
                    throw in.error(l.at(0), what + "; this looks like a face: does the header at " + header.position(0) + " count too many points?");
                }
                throw in.error(l.size() > 3 ? l.at(3) : l.end(), what);
            }
            for (int k = 0; k < 3; k++) positions[3 * i + k] = in.number(l, k, "point " + i + " " + "xyz".charAt(k));
        }

        int[] sizes = new int[faceRoom];
        List<Integer> corners = new ArrayList<>();
        for (int f = 0; f < faces; f++) {
            if (f == sizes.length) sizes = Arrays.copyOf(sizes, (int) Math.min(faces, 2L * f + 16));
            Line l = in.next();
            if (l == null) throw in.errorAtEnd("the file ends after " + f + " of the " + faces + " faces the header announces (at " + header.position(1) + ")");
            // Three numbers that do not start with a 2 (a face too small) are a point too many.
            if (f == 0 && l.size() == 3 && in.isNumber(l, 0) && in.isNumber(l, 1) && in.isNumber(l, 2)
                    && !(INTEGER.matcher(l.text(0)).matches() && l.text(0).replace("+", "").equals("2"))) {
                throw in.error(l.at(0), "expected face 0 ('n i0 i1 ...'), found a point: does the header at " + header.position(0)
                        + " count too few points?");
            }
            long n = in.integer(l, 0, "face " + f + " vertex count");
            if (n < 3) throw in.error(l.at(0), "face " + f + " has " + n + " vertices, expected at least 3");
            if (l.size() - 1 != n) {
                throw in.error(l.size() - 1 > n ? l.at((int) n + 1) : l.end(),
                        "face " + f + " says " + n + " vertices but lists " + plural(l.size() - 1, "index", "indices"));
            }
            sizes[f] = (int) n;
            for (int j = 1; j <= n; j++) {
                long v = in.integer(l, j, "face " + f + " vertex index");
                if (v < 0 || v >= points) {
                    throw in.error(l.at(j), "face " + f + " uses point " + v + ", out of range (the mesh has " + points
                            + " points, numbered from 0)");
                }
                corners.add((int) v);
            }
        }
        Line extra = in.next();
        if (extra != null) {
            throw in.error(extra.at(0), "unexpected " + extra.describe() + " after the last of the " + faces
                    + " faces the header announces (at " + header.position(1) + ")");
        }
        int[] vi = new int[corners.size()];
        for (int i = 0; i < vi.length; i++) vi[i] = corners.get(i);
        return new MeshData(positions, null, null, sizes, vi, null, null, fileName);
    }

    /**
     * Reads a {@code .tex} unwrap for {@code mesh}, in either form (told apart by the header):
     * texture points with faces of their own, or one point per face corner.
     *
     * @param file the file
     * @param mesh the mesh it unwraps
     * @return the texture coordinates; {@link Unwrap#applyTo} gives them to the control mesh
     * @throws IOException if the file cannot be read
     */
    public static Unwrap readTex(Path file, MeshData mesh) throws IOException {
        return parseTex(readText(file, "unwrap"), file.toString(), mesh);
    }

    /**
     * Parses {@code .tex} unwrap text for {@code mesh}; see {@link #readTex}.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @param mesh the mesh it unwraps
     * @return the texture coordinates
     */
    public static Unwrap parseTex(String text, String fileName, MeshData mesh) {
        Lines in = new Lines(text, fileName);
        Line header = in.next();
        if (header == null) {
            throw in.errorAtEnd("empty unwrap file: expected the header 'point_count face_count' (texture points and faces) or 'corner_count' (one point per face corner)");
        }
        // The form is the header's: two integers for points and faces (as a .dat mesh), one for corners.
        if (header.size() == 2) return parsePointsAndFaces(in, header, mesh);
        if (header.size() != 1) {
            throw in.error(header.at(2), "expected the header 'point_count face_count' (two integers: texture points and faces) or 'corner_count' "
                    + "(one integer: one point per face corner), found " + header.describe());
        }
        return new Unwrap(parseCorners(in, header, mesh), null);
    }

    /**
     * Reads a {@code .tex} unwrap for {@code mesh} as one (u, v) per face corner, face after face,
     * whichever form the file has. A points-and-faces unwrap is expanded, which drops its own
     * sharing of points; {@link #readTex} keeps it.
     *
     * @param file the file
     * @param mesh the mesh it unwraps
     * @return (u, v) pairs, two doubles per face corner
     * @throws IOException if the file cannot be read
     */
    public static double[] readUnwrap(Path file, MeshData mesh) throws IOException {
        return readTex(file, mesh).cornerUvs();
    }

    /**
     * Parses {@code .tex} unwrap text for {@code mesh}; see {@link #readUnwrap}.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @param mesh the mesh it unwraps
     * @return (u, v) pairs, two doubles per face corner
     */
    public static double[] parseUnwrap(String text, String fileName, MeshData mesh) {
        return parseTex(text, fileName, mesh).cornerUvs();
    }

    /** The one-point-per-corner form after its header: (u, v) for every face corner. */
    private static double[] parseCorners(Lines in, Line header, MeshData mesh) {
        int expected = mesh.vertexIndex().length;
        int count = in.count(header, 0, "corner count", 0);
        if (count != expected) {
            throw in.error(header.at(0), "the unwrap has " + plural(count, "corner") + " but " + meshName(mesh) + " has " + plural(expected, "face corner")
                    + " (one 'u v' per corner, face after face)");
        }
        // As for a mesh: the array is sized by what the rest of the file can hold ('0 0' and a line break).
        int room = (int) Math.min(count, (in.remaining() + 1) / MIN_CORNER_LINE);
        double[] uv = new double[2 * room];
        for (int i = 0; i < count; i++) {
            if (2 * i == uv.length) uv = Arrays.copyOf(uv, 2 * (int) Math.min(count, 2L * i + 16));
            Line l = in.next();
            if (l == null) throw in.errorAtEnd("the file ends after " + i + " of the " + count + " corners the header announces (at " + header.position(0) + ")");
            if (l.size() != 2) {
                throw in.error(l.size() > 2 ? l.at(2) : l.end(), "corner " + i + " has " + plural(l.size(), "number") + ", expected 2 (u v)");
            }
            uv[2 * i] = in.number(l, 0, "corner " + i + " u");
            uv[2 * i + 1] = in.number(l, 1, "corner " + i + " v");
        }
        Line extra = in.next();
        if (extra != null) {
            throw in.error(extra.at(0), "unexpected " + extra.describe() + " after the last of the " + count
                    + " corners the header announces (at " + header.position(0) + ")");
        }
        return uv;
    }

    /**
     * The thesis's form after its header: texture points ({@code u v}, or {@code u v w} with w
     * ignored, as Workframe kept them in a mesh's point structure), then one face per face of the
     * mesh, of the same size, whose indices name texture points.
     */
    private static Unwrap parsePointsAndFaces(Lines in, Line header, MeshData mesh) {
        int[] meshSizes = mesh.faceSizes();
        int points = in.count(header, 0, "texture point count", 1);
        int faces = in.count(header, 1, "face count", 1);
        if (faces != meshSizes.length) {
            throw in.error(header.at(1), "the unwrap has " + plural(faces, "face") + " but " + meshName(mesh) + " has " + meshSizes.length
                    + " (one texture face per face of the mesh, in the same order)");
        }
        // As for a mesh, the header is not trusted with memory: refused if the rest of the file has
        // no room for its lines, and the points array sized by what the rest can hold ('0 0' and a
        // line break). The corner indices are as many as the mesh's corners, already in memory.
        long rest = in.remaining(), room = (rest + 1) / 2;
        if (points > room || (long) points + faces > room) {
            throw in.error(header.at(points > room ? 0 : 1), "the header announces " + plural(points, "texture point") + " and " + plural(faces, "face")
                    + ", but the rest of the file (" + plural(rest, "character") + ") has room for at most " + plural(room, "line"));
        }
        int corners = mesh.vertexIndex().length;
        int pointRoom = (int) Math.min(points, (rest + 1) / MIN_CORNER_LINE);
        try {
            HeapBudget.require(HeapBudget.sum(HeapBudget.product(pointRoom, 2 * 8), HeapBudget.product(corners, 4)),
                    "the unwrap's " + plural(points, "texture point") + " and " + plural(corners, "face corner"));
        } catch (IllegalArgumentException e) {
            throw in.error(header.at(0), e.getMessage());
        }

        double[] uv = new double[2 * pointRoom];
        int arity = 0; // numbers per point, set by the first: every point 'u v' or every point 'u v w'
        Line first = null;
        for (int i = 0; i < points; i++) {
            if (2 * i == uv.length) uv = Arrays.copyOf(uv, 2 * (int) Math.min(points, 2L * i + 16));
            Line l = in.next();
            if (l == null) {
                throw in.errorAtEnd("the file ends after " + i + " of the " + points + " texture points the header announces (at " + header.position(0) + ")");
            }
            if (l.size() != 2 && l.size() != 3) {
                String what = "texture point " + i + " has " + plural(l.size(), "number") + ", expected 2 (u v) or 3 (u v w, w ignored)";
                if (i > 0 && looksLikeFace(l)) {
                    throw in.error(l.at(0), what + "; this looks like a face: does the header at " + header.position(0) + " count too many points?");
                }
                throw in.error(l.size() > 3 ? l.at(3) : l.end(), what);
            }
            if (first == null) {
                first = l;
                arity = l.size();
            } else if (l.size() != arity) {
                throw in.error(l.size() > arity ? l.at(arity) : l.end(), "texture point " + i + " has " + plural(l.size(), "number") + " but point 0 (at "
                        + first.position(0) + ") has " + arity + " (every point 'u v', or every point 'u v w')");
            }
            uv[2 * i] = in.number(l, 0, "texture point " + i + " u");
            uv[2 * i + 1] = in.number(l, 1, "texture point " + i + " v");
            if (arity == 3) in.number(l, 2, "texture point " + i + " w"); // checked, not kept
        }

        int[] index = new int[corners];
        for (int f = 0, c = 0; f < faces; f++) {
            Line l = in.next();
            if (l == null) throw in.errorAtEnd("the file ends after " + f + " of the " + faces + " faces the header announces (at " + header.position(1) + ")");
            // Two or three numbers are no face (a face has at least 3 indices): a point too many,
            // unless they start as the face should (its corner count, then indices): a short face.
            if (f == 0 && l.size() <= 3 && allNumbers(in, l) && !(allIntegers(l) && l.text(0).replace("+", "").equals(String.valueOf(meshSizes[0])))) {
                throw in.error(l.at(0), "expected face 0 ('n i0 i1 ...'), found a point: does the header at " + header.position(0)
                        + " count too few points?");
            }
            long n = in.integer(l, 0, "face " + f + " corner count");
            if (n != meshSizes[f]) {
                throw in.error(l.at(0), "face " + f + " has " + plural(n, "corner") + " but face " + f + " of " + meshName(mesh) + " has " + meshSizes[f]
                        + " (a texture face has the corners of its mesh face, in the same order)");
            }
            if (l.size() - 1 != n) {
                throw in.error(l.size() - 1 > n ? l.at((int) n + 1) : l.end(),
                        "face " + f + " says " + n + " corners but lists " + plural(l.size() - 1, "index", "indices"));
            }
            for (int j = 1; j <= n; j++, c++) {
                long t = in.integer(l, j, "face " + f + " texture point index");
                if (t < 0 || t >= points) {
                    throw in.error(l.at(j), "face " + f + " uses texture point " + t + ", out of range (the unwrap has " + plural(points, "point")
                            + ", numbered from 0)");
                }
                index[c] = (int) t;
            }
        }
        Line extra = in.next();
        if (extra != null) {
            throw in.error(extra.at(0), "unexpected " + extra.describe() + " after the last of the " + faces
                    + " faces the header announces (at " + header.position(1) + ")");
        }
        return new Unwrap(uv.length == 2 * points ? uv : Arrays.copyOf(uv, 2 * points), index);
    }

    private static String meshName(MeshData mesh) {
        return mesh.source() == null ? "the mesh" : "the mesh " + mesh.source();
    }

    private static boolean allIntegers(Line l) {
        for (int i = 0; i < l.size(); i++) if (!INTEGER.matcher(l.text(i)).matches()) return false;
        return true;
    }

    private static boolean allNumbers(Lines in, Line l) {
        for (int i = 0; i < l.size(); i++) if (!in.isNumber(l, i)) return false;
        return true;
    }

    /** n followed by n integers, n at least 3. */
    private static boolean looksLikeFace(Line l) {
        if (l.size() < 4 || !INTEGER.matcher(l.text(0)).matches()) return false;
        for (int i = 1; i < l.size(); i++) if (!INTEGER.matcher(l.text(i)).matches()) return false;
        try {
            return Long.parseLong(l.text(0).replace("+", "")) == l.size() - 1;
        } catch (NumberFormatException e) {
            return false;
        }
    }

    private static String plural(long n, String word) {
        return plural(n, word, word + "s");
    }

    private static String plural(long n, String one, String many) {
        return n + " " + (n == 1 ? one : many);
    }

    private static String readText(Path file, String what) throws IOException {
        String name = file.toString();
        byte[] bytes;
        // A pipe would block and a device never end: only regular files are opened.
        String problem = InputFiles.problem(file);
        if (problem != null) {
            throw new SceneException(name, 0, 0, what + " file " + problem + " (looked in " + file.toAbsolutePath().normalize() + ")");
        }
        try {
            // Decoding to a String holds the bytes and two bytes per char at once.
            bytes = InputFiles.readAllBytes(file, what + " file", 3);
        } catch (InsufficientMemoryException e) {
            throw new SceneException(name, 0, 0, e.getMessage(), e);
        } catch (NoSuchFileException e) {
            throw new SceneException(name, 0, 0, what + " file not found (looked in " + file.toAbsolutePath().normalize() + ")");
        } catch (IOException e) {
            throw new SceneException(name, 0, 0, "cannot read " + what + " file: " + e.getMessage(), e);
        }
        return SceneLexer.decodeUtf8(bytes, name, "the " + what + " file");
    }

    /** One line's tokens with their 1-based columns. */
    private record Line(int number, List<String> tokens, int[] columns) {
        int size() { return tokens.size(); }
        String text(int i) { return tokens.get(i); }
        int[] at(int i) { return new int[] {number, columns[i]}; }
        /** Just after the last token: where a missing number would have been. */
        int[] end() {
            int last = tokens.size() - 1;
            return new int[] {number, columns[last] + tokens.get(last).length()};
        }
        String position(int i) { return number + ":" + columns[i]; }

        String describe() {
            if (tokens.isEmpty()) return "an empty line";
            // Joined only as far as a message shows: a line may hold a huge token, or very many.
            int show = MessageText.SHOWN + MessageText.SLACK + 1;
            StringBuilder head = new StringBuilder();
            long length = -1;
            for (String t : tokens) {
                length += 1 + t.length();
                if (head.length() < show) {
                    if (head.length() > 0) head.append(' ');
                    head.append(t, 0, Math.min(t.length(), show));
                }
            }
            return MessageText.quote(head.toString(), length, "'");
        }
    }

    /** The non-blank, comment-stripped lines of a text, one at a time. */
    private static final class Lines {
        private final String text, file;
        private int pos, line;
        /** Line and column just after the last character, for "the file ends" messages. */
        private int endLine = 1, endColumn = 1;

        Lines(String text, String file) {
            this.text = text.startsWith("\uFEFF") ? text.substring(1) : text;
            this.file = file;
        }

        /** Characters not yet read (after the last line returned). */
        long remaining() {
            return text.length() - pos;
        }

        /** The next line with at least one token, or null at the end of the text. */
        Line next() {
            while (pos < text.length()) {
                line++;
                int start = pos;
                int stop = start;
                while (stop < text.length() && text.charAt(stop) != '\n' && text.charAt(stop) != '\r') stop++;
                pos = stop;
                if (pos < text.length()) {
                    if (text.charAt(pos) == '\r' && pos + 1 < text.length() && text.charAt(pos + 1) == '\n') pos++;
                    pos++;
                }
                endLine = line;
                endColumn = stop - start + 1;
                List<String> tokens = new ArrayList<>();
                List<Integer> cols = new ArrayList<>();
                int i = start;
                while (i < stop) {
                    char c = text.charAt(i);
                    if (c == '#') break;
                    if (Character.isWhitespace(c)) {
                        i++;
                        continue;
                    }
                    int t = i;
                    while (i < stop && !Character.isWhitespace(text.charAt(i)) && text.charAt(i) != '#') i++;
                    tokens.add(text.substring(t, i));
                    cols.add(t - start + 1);
                }
                if (pos >= text.length() && stop < text.length()) {
                    // The text ends with a line break: the end is the start of the (empty) next line.
                    endLine = line + 1;
                    endColumn = 1;
                }
                if (!tokens.isEmpty()) {
                    int[] c = new int[cols.size()];
                    for (int k = 0; k < c.length; k++) c[k] = cols.get(k);
                    return new Line(line, tokens, c);
                }
            }
            return null;
        }

        SceneException error(int[] at, String message) {
            return new SceneException(file, at[0], at[1], message);
        }

        SceneException errorAtEnd(String message) {
            return new SceneException(file, endLine, endColumn, message);
        }

        boolean isNumber(Line l, int i) {
            return NUMBER.matcher(l.text(i)).matches();
        }

        long integer(Line l, int i, String what) {
            String t = l.text(i);
            if (!INTEGER.matcher(t).matches()) throw error(l.at(i), "expected an integer for the " + what + ", found " + MessageText.quote(t));
            try {
                return Long.parseLong(t.startsWith("+") ? t.substring(1) : t);
            } catch (NumberFormatException e) {
                throw error(l.at(i), "integer " + MessageText.quote(t, "") + " is out of range for the " + what);
            }
        }

        /** A count in a header: an integer from {@code min} that fits an array. */
        int count(Line l, int i, String what, int min) {
            long v = integer(l, i, what);
            if (v < min || v > 100_000_000) {
                throw error(l.at(i), what + " must be between " + min + " and 100000000, found " + v);
            }
            return (int) v;
        }

        double number(Line l, int i, String what) {
            String t = l.text(i);
            if (!NUMBER.matcher(t).matches()) throw error(l.at(i), "expected a number for " + what + ", found " + MessageText.quote(t));
            double v = Double.parseDouble(t);
            // Bounded so that squares and products of coordinates cannot overflow (see Ranges).
            if (!Ranges.isModest(v)) {
                throw error(l.at(i), "number " + MessageText.quote(t, "") + " is too large for " + what + " (mesh numbers are at most "
                        + Ranges.show(Ranges.MAX_NUMBER) + " in magnitude)");
            }
            return v;
        }
    }
}
