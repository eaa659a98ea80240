package lt.spindulys.subdiv;

import java.util.Locale;

/**
 * OpenSubdiv's OBJ tag lines, as in its regression shapes:
 * {@code t <name> <nints>/<nfloats>/<nstrings> ints... floats... strings...}.
 *
 * <ul>
 * <li>{@code crease}: vertex pairs (a b), with one sharpness for all pairs or one per pair;
 * <li>{@code corner}: vertices, with one sharpness for all or one per vertex;
 * <li>{@code hole}: face indices;
 * <li>{@code interpolateboundary} n: 0 NONE, 1 EDGE_AND_CORNER, 2 EDGE_ONLY;
 * <li>{@code facevaryinginterpolateboundary} n: 0 NONE, 1 CORNERS_ONLY, 2 CORNERS_PLUS1,
 * 3 CORNERS_PLUS2, 4 BOUNDARIES, 5 ALL;
 * <li>{@code creasemethod} {@code normal|chaikin}; {@code smoothtriangles} {@code catmark|smooth}.
 * </ul>
 * Indices are 0-based. The hierarchical edits ({@code vertexedit}, {@code edgeedit},
 * {@code faceedit}) and {@code facevaryingpropagatecorners} are parsed but ignored, as Far
 * ignores them. Malformed lines and unknown tags throw {@link IllegalArgumentException}.
 */
public final class SubdivTags {
    private SubdivTags() {}

    /** A parsed tag line. */
    public record Tag(String name, int[] ints, float[] floats, String[] strings) {}

    /** Parses one line (with or without its leading {@code t}). */
    public static Tag parse(String line) {
        String[] tok = line.trim().split("\\s+");
        int i = 0;
        if (tok.length > 0 && tok[0].equals("t")) i++;
        if (tok.length - i < 2 || tok[i].isEmpty()) throw new IllegalArgumentException("tag line needs a name and counts n/n/n: '" + line + "'");
        String name = tok[i++];
        String[] counts = tok[i++].split("/");
        if (counts.length != 3) throw new IllegalArgumentException("tag '" + name + "': counts must be ints/floats/strings, found '" + tok[i - 1] + "'");
        int ni, nf, ns;
        try {
            ni = Integer.parseInt(counts[0]);
            nf = Integer.parseInt(counts[1]);
            ns = Integer.parseInt(counts[2]);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("tag '" + name + "': counts must be numbers, found '" + tok[i - 1] + "'");
        }
        if (ni < 0 || nf < 0 || ns < 0 || tok.length - i != (long) ni + nf + ns) {
            throw new IllegalArgumentException("tag '" + name + "' announces " + ni + "/" + nf + "/" + ns + " arguments but has " + (tok.length - i));
        }
        int[] ints = new int[ni];
        float[] floats = new float[nf];
        String[] strings = new String[ns];
        try {
            for (int k = 0; k < ni; k++) ints[k] = Integer.parseInt(tok[i++]);
            for (int k = 0; k < nf; k++) floats[k] = Float.parseFloat(tok[i++]);
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("tag '" + name + "': bad number '" + tok[i - 1] + "'");
        }
        for (int k = 0; k < ns; k++) strings[k] = tok[i++];
        return new Tag(name, ints, floats, strings);
    }

    /** Parses a line and applies it; see {@link #apply(Tag, ControlMesh.Builder)}. */
    public static boolean apply(String line, ControlMesh.Builder builder) {
        return apply(parse(line), builder);
    }

    /**
     * Applies a tag to a builder. Returns false for the tags Far ignores, true otherwise.
     * Index ranges are checked when the builder builds.
     */
    public static boolean apply(Tag t, ControlMesh.Builder b) {
        int[] in = t.ints();
        float[] fl = t.floats();
        switch (t.name()) {
            case "crease" -> {
                if (in.length < 2 || in.length % 2 != 0) throw bad(t, "needs vertex pairs");
                int pairs = in.length / 2;
                if (fl.length != 1 && fl.length != pairs) throw bad(t, "needs 1 sharpness or one per pair");
                for (int k = 0; k < pairs; k++) b.crease(in[2 * k], in[2 * k + 1], fl.length == 1 ? fl[0] : fl[k]);
            }
            case "corner" -> {
                if (in.length < 1) throw bad(t, "needs vertices");
                if (fl.length != 1 && fl.length != in.length) throw bad(t, "needs 1 sharpness or one per vertex");
                for (int k = 0; k < in.length; k++) b.corner(in[k], fl.length == 1 ? fl[0] : fl[k]);
            }
            case "hole" -> {
                for (int f : in) b.hole(f);
            }
            case "interpolateboundary" -> {
                SubdivOptions.Boundary[] modes = {SubdivOptions.Boundary.NONE, SubdivOptions.Boundary.EDGE_AND_CORNER, SubdivOptions.Boundary.EDGE_ONLY};
                b.options(b.options().withBoundary(modes[choice(t, modes.length)]));
            }
            case "facevaryinginterpolateboundary" -> {
                SubdivOptions.FaceVarying[] modes = {SubdivOptions.FaceVarying.NONE, SubdivOptions.FaceVarying.CORNERS_ONLY,
                        SubdivOptions.FaceVarying.CORNERS_PLUS1, SubdivOptions.FaceVarying.CORNERS_PLUS2,
                        SubdivOptions.FaceVarying.BOUNDARIES, SubdivOptions.FaceVarying.ALL};
                b.options(b.options().withFaceVarying(modes[choice(t, modes.length)]));
            }
            case "creasemethod" -> {
                String s = word(t);
                if (s.equals("normal")) b.options(b.options().withCreasing(SubdivOptions.Creasing.UNIFORM));
                else if (s.equals("chaikin")) b.options(b.options().withCreasing(SubdivOptions.Creasing.CHAIKIN));
                else throw bad(t, "expects normal or chaikin, found '" + s + "'");
            }
            case "smoothtriangles" -> {
                String s = word(t);
                if (s.equals("catmark")) b.options(b.options().withTriangles(SubdivOptions.Triangles.CATMARK));
                else if (s.equals("smooth")) b.options(b.options().withTriangles(SubdivOptions.Triangles.SMOOTH));
                else throw bad(t, "expects catmark or smooth, found '" + s + "'");
            }
            case "vertexedit", "edgeedit", "faceedit", "facevaryingpropagatecorners" -> {
                return false;
            }
            default -> throw new IllegalArgumentException("unknown subdivision tag '" + t.name() + "'");
        }
        return true;
    }

    private static int choice(Tag t, int n) {
        if (t.ints().length != 1) throw bad(t, "needs one integer");
        int c = t.ints()[0];
        if (c < 0 || c >= n) throw bad(t, "value " + c + " is not in 0.." + (n - 1));
        return c;
    }

    private static String word(Tag t) {
        if (t.strings().length != 1) throw bad(t, "needs one word");
        return t.strings()[0].toLowerCase(Locale.ROOT);
    }

    private static IllegalArgumentException bad(Tag t, String what) {
        return new IllegalArgumentException("tag '" + t.name() + "' " + what);
    }
}
