package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;

/**
 * Malformed scenes and the exact error each must produce, shared by the parser's table test and
 * by tests of the command line (which also check that no image is written). To add a case, append
 * one line to {@link #scenes()}; a case may bring files (meshes) to be written next to the scene.
 */
public final class BadInputCases {
    private BadInputCases() {}

    /**
     * One malformed scene, with the files it refers to.
     *
     * @param name      short description, shown as the test's name
     * @param scene     the scene text
     * @param expected  "line:column: message" as reported after the file name; {@code ${dir}}
     *                  stands for the absolute folder relative paths are resolved against
     * @param files     further files (name relative to the scene's folder, then content) that
     *                  must be written next to the scene
     * @param errorFile the file, among {@code files}, that the error is in; null for the scene itself
     */
    public record Case(String name, String scene, String expected, Map<String, String> files, String errorFile) {
        public Case(String name, String scene, String expected) {
            this(name, scene, expected, Map.of(), null);
        }

        /** The full message expected for a scene read as {@code fileName} with paths relative to {@code baseDir}. */
        public String expectedMessage(String fileName, Path baseDir) {
            return expectedFile(fileName, baseDir) + ":" + expected.replace("${dir}", baseDir.toAbsolutePath().normalize().toString());
        }

        /** The file the message must name: the scene as named, or the other file as the parser resolved it. */
        public String expectedFile(String fileName, Path baseDir) {
            return errorFile == null ? fileName : baseDir.toAbsolutePath().normalize().resolve(errorFile).toString();
        }

        /** Writes {@link #files} into {@code dir}: as UTF-8, or as raw bytes when made by {@link BadInputCases#bytes}. */
        public void writeFiles(Path dir) throws IOException {
            for (Map.Entry<String, String> f : files.entrySet()) {
                Path p = dir.resolve(f.getKey());
                Files.createDirectories(p.getParent());
                String content = f.getValue();
                if (content.startsWith(BYTES)) Files.write(p, content.substring(BYTES.length()).getBytes(StandardCharsets.ISO_8859_1));
                else Files.writeString(p, content);
            }
        }

        @Override public String toString() { return name; }
    }

    private static Case c(String name, String scene, String expected) { return new Case(name, scene, expected); }

    /** Marks file content that {@link Case#writeFiles} writes as bytes (one per character, 0-255), not as UTF-8. */
    private static final String BYTES = "\uE000bytes:";

    /** File content written byte for byte: each character of {@code latin1} is one byte (for files that are not UTF-8). */
    static String bytes(String latin1) { return BYTES + latin1; }

    /** {@code n} copies of {@code c}: a token far longer than a message should show. */
    private static String run(char c, int n) { return String.valueOf(c).repeat(n); }

    private static final int MB = 1 << 20;

    /** A case whose scene refers to {@code file} with {@code content}; {@code errorInFile}: the error is reported in that file. */
    private static Case withFile(String name, String scene, String file, String content, boolean errorInFile, String expected) {
        return new Case(name, scene, expected, Map.of(file, content), errorInFile ? file : null);
    }

    /** As {@link #withFile}, with two files; the error is in the second. */
    private static Case withFiles(String name, String scene, String file1, String content1, String file2, String content2, String expected) {
        return new Case(name, scene, expected, Map.of(file1, content1, file2, content2), file2);
    }

    private static final String CUBE_DAT = "8 6\n-1 -1 -1\n1 -1 -1\n1 1 -1\n-1 1 -1\n-1 -1 1\n1 -1 1\n1 1 1\n-1 1 1\n"
            + "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 0 4 7 3\n";
    private static final String TRI_OBJ = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";
    private static final String QUAD_OBJ = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n";

    /**
     * {@code levels} CSG blocks nested one in another, one keyword a line from line 1 (unions, or
     * differences and intersections alternating), each with a sphere beside the nested block.
     */
    static String nestedCsg(int levels, boolean alternate) {
        StringBuilder b = new StringBuilder(levels * 60);
        for (int i = 0; i < levels; i++) b.append(!alternate ? "union" : i % 2 == 0 ? "difference" : "intersection").append(" {\n");
        b.append("sphere { }\nsphere { center 0.5 0 0 }\n");
        for (int i = levels - 1; i >= 0; i--) {
            b.append(alternate && i % 2 == 0 ? "sphere { center 0 0 -3  radius 0.1 }\n" : "sphere { radius 0.9 }\n").append("}\n");
        }
        return b.toString();
    }

    /** An uncompressed 24-bit TGA header (type 2, top-left origin) for 16384 x 4097 pixels, without pixels. */
    private static final String HUGE_TGA_HEADER = "\0\0\u0002\0\0\0\0\0\0\0\0\0\u0000\u0040\u0001\u0010\u0018\u0020";

    /** What the texture cache says about a file that is not an image it can decode. */
    static final String UNREADABLE_IMAGE = "not a PNG, JPEG, BMP, GIF or TGA image (no decoder recognises its contents; .hdr, .pfm and .exr files are read by their extension)";

    /** Every case; none of them must produce an image. */
    public static List<Case> scenes() {
        String cam = "camera { eye 0 0 -5  lookat 0 0 0 }\n";
        return List.of(
                // ---- lexical ----
                c("bad number", "sphere { radius 1.2.3 }", "1:17: malformed number '1.2.3'"),
                c("number glued to letters", "sphere { radius 2x }", "1:17: malformed number '2x'"),
                c("NaN word", "sphere { radius NaN }", "1:17: expected a number for 'radius', found 'NaN' (NaN and Infinity are not allowed)"),
                c("signed infinity", "sphere { center 0 -Infinity 0 }", "1:19: NaN and Infinity are not allowed, found '-Infinity'"),
                c("number overflows", "sphere { radius 1e999 }", "1:17: number '1e999' is out of range"),
                c("unterminated string", "sphere {\n  name \"ball\n}", "2:8: unterminated string (a string must end with \" on the same line)"),
                c("unknown escape", "sphere { name \"a\\tb\" }", "1:17: unknown escape '\\t' in string (only \\\" and \\\\ are allowed)"),
                c("equals sign", "sphere { radius=1 }", "1:16: unexpected character '=' after 'radius' (write a value after its key, separated by a space)"),
                c("stray character", "sphere { radius 1 } @", "1:21: unexpected character '@'"),
                // ---- structure ----
                c("unknown statement", "shpere { radius 1 }", "1:1: unknown statement 'shpere' (did you mean 'sphere'?)"),
                c("property outside a block", "sphere { } radius 2", "1:12: unknown statement 'radius' ('radius' is a property of disclight, spherelight, sphere or cylinder: was a block closed too early?)"),
                // A decimal: a scene whose first token is an integer is taken for a Workframe mesh (see CliBadInputTest).
                c("number as statement", "4.2", "1:1: expected a statement (settings, animation, camera, light, rectlight, disclight, spherelight, environment, texture, material, sphere, plane, box, cylinder, triangle, mesh, subdiv, "
                        + "union, intersection, difference), found '4.2'"),
                c("stray closing brace", cam + "}", "2:1: unexpected '}': no block is open"),
                c("missing '{'", "sphere radius 1 }", "1:8: expected '{' after 'sphere', found 'radius'"),
                c("missing '{' at end of file", "box", "1:4: expected '{' after 'box', found end of file"),
                c("unclosed block", cam + "sphere {\n  radius 1\n", "4:1: unexpected end of file: missing '}' to close 'sphere' opened at 2:1"),
                c("unclosed inline material", "sphere { material { kd 0.5 ", "1:28: unexpected end of file: missing '}' to close 'material' opened at 1:10"),
                c("missing '}' before next object", "sphere { radius 1\nsphere { radius 2 }", "2:1: unknown property 'sphere' in sphere (is a '}' missing to close 'sphere' opened at 1:1?)"),
                c("number where a key belongs", "sphere { 1 }", "1:10: expected a property of sphere or '}', found '1'"),
                // ---- keys ----
                c("unknown key with suggestion", "sphere {\n  radus 1\n}", "2:3: unknown property 'radus' in sphere (did you mean 'radius'?)"),
                c("unknown key, common key suggested", "box { min 0 0 0 max 1 1 1 translat 1 0 0 }", "1:27: unknown property 'translat' in box (did you mean 'translate'?)"),
                c("unknown key without suggestion", "light { position 0 1 0 shadow true }", "1:24: unknown property 'shadow' in light"),
                c("unknown key in named material", "material red { colr 1 0 0 }", "1:16: unknown property 'colr' in material 'red' (did you mean 'color'?)"),
                c("duplicate key", "sphere {\n  radius 1\n  radius 2\n}", "3:3: 'radius' given twice in sphere (first at 2:3)"),
                c("duplicate material key", "sphere { material { kd 1 } material { kd 2 } }", "1:28: 'material' given twice in sphere (first at 1:10)"),
                c("box missing 'min'", "box { max 1 1 1 }", "1:1: box needs 'min'"),
                c("camera missing eye and lookat", "camera { fov 30 }", "1:1: camera needs 'eye' and 'lookat'"),
                c("light missing position", "light { intensity 2 }", "1:1: light needs 'position'"),
                c("triangle missing vertices", "triangle { }", "1:1: triangle needs 'vertices'"),
                c("mesh missing file", "mesh { shading flat }", "1:1: mesh needs 'file'"),
                // ---- values ----
                c("missing number", "sphere { radius }", "1:17: expected a number for 'radius', found '}'"),
                c("word instead of number", "sphere { radius abc }", "1:17: expected a number for 'radius', found 'abc'"),
                c("vector too short", "sphere { center 1 2 }", "1:21: expected 3 numbers for 'center', found '}'"),
                c("colour with two numbers", "material m { color 1 0 }", "1:24: expected 1 or 3 numbers for 'color', found '}'"),
                c("triangle with 8 numbers", "triangle { vertices 0 0 0  1 0 0  0 1 }", "1:39: expected 9 numbers (3 points) for 'vertices', found '}'"),
                c("integer expected", "settings { width 1.5 }", "1:18: expected an integer for 'width', found '1.5'"),
                c("integer with exponent", "settings { samples 1e2 }", "1:20: expected an integer for 'samples', found '1e2'"),
                c("integer out of range", "settings { height 99999999999 }", "1:19: integer 99999999999 is out of range for 'height'"),
                c("seed out of range", "settings { seed 99999999999999999999 }", "1:17: integer 99999999999999999999 is out of range for 'seed'"),
                c("bad encoding", "settings { encoding gamma }", "1:21: expected linear or srgb for 'encoding', found 'gamma'"),
                c("unknown accelerator", "settings { accelerator grid }", "1:24: expected bvh, bvh-compact, bvh2, octree or bruteforce for 'accelerator', found 'grid'"),
                c("unknown aov", "settings { aov depth shadow }", "1:22: expected depth, normal, object, albedo or noise for 'aov', found 'shadow'"),
                c("misspelt aov", "settings {\n  aov normall\n}", "2:7: expected depth, normal, object, albedo or noise for 'aov', found 'normall' (did you mean 'normal'?)"),
                c("aov listed twice", "settings { aov depth normal depth }", "1:29: 'depth' listed twice for 'aov'"),
                c("empty aov list", "settings { aov }", "1:16: expected depth, normal, object, albedo or noise for 'aov', found '}'"),
                c("aov list running into a statement", "settings { aov depth\ncamera { eye 0 0 -5 lookat 0 0 0 }", "2:1: expected depth, normal, object, albedo or noise for 'aov', found 'camera' (is a '}' missing to close 'settings'?)"),
                c("bad falloff", "light { position 0 5 0  falloff inverse_square }", "1:33: expected none or inverse-square for 'falloff', found 'inverse_square' (did you mean 'inverse-square'?)"),
                c("bad boolean", "material m { fresnel yes }", "1:22: expected true or false for 'fresnel', found 'yes'"),
                c("bad shading", "mesh { file \"a.obj\" shading smoth }", "1:29: expected smooth or flat for 'shading', found 'smoth' (did you mean 'smooth'?)"),
                c("name without quotes", "sphere { name ball }", "1:15: expected a string in double quotes for 'name', found 'ball'"),
                c("bad rotate axis", "sphere { rotate w 30 }", "1:17: expected x, y, z or an axis (3 numbers) for 'rotate', found 'w'"),
                c("rotate missing angle", "sphere { rotate y }", "1:19: expected an angle in degrees for 'rotate', found '}'"),
                c("material name missing", "material { kd 1 }", "1:10: expected a material name after 'material', found '{'"),
                c("material name quoted", "material \"red\" { kd 1 }", "1:10: expected a material name after 'material', found string \"red\" (material names are bare words, without quotes)"),
                c("named material missing '{'", "material red kd 1", "1:14: expected '{' after 'material red', found 'kd'"),
                c("material reference is a number", "sphere { material 3 }", "1:19: expected a material name or '{' after 'material', found '3'"),
                // ---- builder validation, reported at the key ----
                c("width 0", "settings {\n  width 0\n}", "2:3: width must be between 1 and 32768, found 0"),
                c("samples 0", "settings { samples 0 }", "1:12: samples per pixel must be between 1 and 65536, found 0"),
                c("maxdepth too deep", "settings { maxdepth 65 }", "1:12: maxdepth must be between 0 and 64, found 65"),
                c("mincontribution 1", "settings { mincontribution 1 }", "1:12: mincontribution must be in [0, 1), found 1.0"),
                c("negative background", "settings { background -1 }", "1:12: background must have components between 0 and 100, found (-1.0, -1.0, -1.0)"),
                c("negative radius", "sphere { center 0 1 0  radius -1 }", "1:24: sphere radius must be a positive number at most 1e15, found -1.0"),
                c("zero scale", "sphere { translate 1 0 0  scale 0 }", "1:27: invalid 'scale': transform is singular (a scale of zero?)"),
                c("zero scale on one axis", "box { min 0 0 0  max 1 1 1  scale 1 0 1 }", "1:29: invalid 'scale': transform is singular (a scale of zero?)"),
                c("zero rotation axis", "sphere { rotate 0 0 0 30 }", "1:10: invalid 'rotate': cannot normalise vector (0.0, 0.0, 0.0)"),
                c("zero-length up vector", "camera { eye 0 0 -5  lookat 0 0 0  up 0 0 0 }", "1:36: camera up vector has zero length"),
                c("camera eye equals lookat", "camera {\n  eye 1 2 3\n  lookat 1 2 3\n}", "2:3: camera eye and lookat are the same point (1.0, 2.0, 3.0)"),
                c("camera fov 180", "camera { eye 0 0 -5  lookat 0 0 0  fov 180 }", "1:36: fov must be between 0 and 180 degrees, found 180.0"),
                c("negative aperture", "camera { eye 0 0 -5  lookat 0 0 0  aperture -0.5 }", "1:36: camera aperture must be a non-negative number, found -0.5"),
                c("focus 0", "camera { eye 0 0 -5  lookat 0 0 0  aperture 0.1  focus 0 }", "1:50: camera focus distance must be a positive number, found 0.0"),
                c("negative focus", "camera { eye 0 0 -5  lookat 0 0 0\n  focus -3 }", "2:3: camera focus distance must be a positive number, found -3.0"),
                c("focus point behind the camera", "camera { eye 0 0 -5  lookat 0 0 0  aperture 0.1  focuspoint 1 0 -9 }",
                        "1:50: camera focus point must be in front of the camera, found (1.0, 0.0, -9.0) at -4.0 along the view direction"),
                c("focus point beside the eye", "camera { eye 0 0 -5  lookat 0 0 0  focuspoint 3 0 -5 }",
                        "1:36: camera focus point must be in front of the camera, found (3.0, 0.0, -5.0) at 0.0 along the view direction"),
                c("focus and focus point", "camera { eye 0 0 -5  lookat 0 0 0  focuspoint 0 0 1\n  focus 6 }", "2:3: camera has both 'focus' and 'focuspoint': give one"),
                c("unknown lens pattern", "camera { eye 0 0 -5  lookat 0 0 0  lens rings }", "1:41: expected concentric or ring for 'lens', found 'rings' (did you mean 'ring'?)"),
                c("negative light intensity", "light { position 0 5 0  intensity -2 }", "1:25: light intensity must be between 0 and 1e15, found -2.0"),
                c("negative material coefficient", "material m { kd -0.5 }", "1:14: kd must be between 0 and 10, found -0.5"),
                c("ior 0", "material m { ior 0 }", "1:14: ior must be a positive number at most 1e15, found 0.0"),
                c("negative inline filter", "sphere { material { filter 1 -1 1 } }", "1:21: filter must have components between 0 and 1, found (1.0, -1.0, 1.0)"),
                c("box of zero thickness", "box { min 0 0 0  max 1 0 1 }", "1:1: box has zero thickness: corners (0.0, 0.0, 0.0) and (1.0, 0.0, 1.0)"),
                c("cylinder base equals top", "cylinder { base 0 1 0  top 0 1 0  radius 1 }", "1:12: cylinder base and top are the same point (0.0, 1.0, 0.0)"),
                c("plane with zero normal", "plane { normal 0 0 0 }", "1:9: plane normal must be a non-zero vector with components at most 1e15 in magnitude, found (0.0, 0.0, 0.0)"),
                c("triangle degenerate", "triangle { vertices 0 0 0  1 0 0  2 0 0 }", "1:1: triangle (0.0, 0.0, 0.0) (1.0, 0.0, 0.0) (2.0, 0.0, 0.0) is degenerate (zero area)"),
                // ---- scene-level rules ----
                c("duplicate camera", cam + "camera { eye 1 1 1  lookat 0 0 0 }", "2:1: camera is already defined at 1:1"),
                c("duplicate settings", "settings { width 10 }\nsettings { height 10 }", "2:1: settings is already defined at 1:1"),
                c("undefined material with suggestion", "material glass { kt 0.9 }\nsphere { material glas }", "2:19: unknown material 'glas' (did you mean 'glass'?)"),
                c("material used before its definition", "sphere { material glass }\nmaterial glass { kt 0.9 }", "1:19: unknown material 'glass' (a material must be defined before the objects that use it)"),
                c("material redefined", "material glass { kt 0.9 }\nmaterial glass { kt 0.8 }", "2:10: material 'glass' is already defined at 1:1"),
                c("missing mesh file", "mesh { file \"models/x.obj\" }", "1:13: mesh file 'models/x.obj' not found (looked in ${dir}/models/x.obj)"),
                // ---- subdivision surfaces ----
                c("subdiv missing file", "subdiv { level 2 }", "1:1: subdiv needs 'file'"),
                c("subdiv file not found", "subdiv {\n  file \"models/cube.obj\"\n}", "2:8: subdivision mesh file 'models/cube.obj' not found (looked in ${dir}/models/cube.obj)"),
                c("subdiv level out of range", "subdiv { file \"cube.obj\"  level 9 }", "1:27: subdivision level must be between 0 and 8, found 9"),
                c("subdiv negative level", "subdiv { level -1  file \"cube.obj\" }", "1:10: subdivision level must be between 0 and 8, found -1"),
                c("subdiv fractional level", "subdiv { file \"cube.obj\"  level 2.5 }", "1:33: expected an integer for 'level', found '2.5'"),
                c("subdiv unknown boundary mode", "subdiv { file \"cube.obj\"  boundary edge_only }", "1:36: expected edge-only, edge-and-corner or none for 'boundary', found 'edge_only' (did you mean 'edge-only'?)"),
                c("subdiv unknown uv interpolation", "subdiv { file \"cube.obj\"  uvinterpolation linear }",
                        "1:43: expected none, corners-only, corners-plus1, corners-plus2, boundaries or all for 'uvinterpolation', found 'linear'"),
                c("subdiv unknown creasing", "subdiv { file \"cube.obj\"  creasing chaikn }", "1:36: expected uniform or chaikin for 'creasing', found 'chaikn' (did you mean 'chaikin'?)"),
                c("subdiv unknown triangle rule", "subdiv { file \"cube.obj\"  triangles loop }", "1:37: expected catmark or smooth for 'triangles', found 'loop'"),
                c("subdiv unknown scheme", "subdiv { file \"cube.obj\"  scheme lop }", "1:34: expected catmark, loop or bilinear for 'scheme', found 'lop' (did you mean 'loop'?)"),
                withFile("subdiv scheme loop on a quad", "subdiv { file \"m.obj\"  scheme loop }", "m.obj", QUAD_OBJ, false,
                        "1:15: ${dir}/m.obj: face 0 has 4 corners; the Loop scheme needs triangles"),
                withFile("subdiv Loop file with a quad", "subdiv {\n  file \"m.obj\"\n}", "m.obj", "v 2 0 0\n" + QUAD_OBJ + "f 2 5 3\nt scheme 0/0/1 loop\n", false,
                        "2:8: ${dir}/m.obj: face 0 has 4 corners; the Loop scheme needs triangles"),
                withFile("subdiv unknown scheme tag", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t scheme 0/0/1 catmull-clark\n", true,
                        "6:16: expected catmark, loop or bilinear for tag 'scheme', found 'catmull-clark'"),
                c("subdiv unknown key", "subdiv { file \"cube.obj\"  levle 2 }", "1:27: unknown property 'levle' in subdiv (did you mean 'level'?)"),
                withFile("subdiv file of another kind", "subdiv { file \"cube.ply\" }", "cube.ply", "ply\n", false,
                        "1:15: subdivision mesh file 'cube.ply' must be a Wavefront .obj or a Workframe .dat file"),
                withFile("subdiv malformed tag line", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t crease 2/1/0 0 1\n", true,
                        "6:19: expected a number for sharpness 1 of 1 of tag 'crease' (its counts 2/1/0 say 2 integers, 1 float and 0 strings), found end of line"),
                withFile("subdiv unknown tag", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t sharpness 1/1/0 0 1\n", true,
                        "6:3: unknown tag 'sharpness' (known: crease, corner, hole, interpolateboundary, facevaryinginterpolateboundary, "
                                + "facevaryingpropagatecorners, creasemethod, smoothtriangles, scheme, vertexedit, edgeedit, faceedit)"),
                withFile("subdiv tag index out of range", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t corner 1/1/0 4 10\n", true,
                        "6:16: corner vertex 4 out of range (the file has 4 vertices; tag indices count from 0)"),
                withFile("subdiv .dat with too few points", "subdiv { file \"m.dat\" }", "m.dat", "4 1\n0 0 0\n1 0 0\n1 1 0\n4 0 1 2 3\n", true,
                        "5:1: point 3 has 5 numbers, expected 3 (x y z); this looks like a face: does the header at 1:1 count too many points?"),
                withFile("subdiv .dat with too many faces", "subdiv { file \"m.dat\" }", "m.dat", "3 2\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n", true,
                        "6:1: the file ends after 1 of the 2 faces the header announces (at 1:3)"),
                // ---- counts in files size nothing before the data arrive (issue 14) ----
                withFile("subdiv .dat header announcing 10^8 points in 12 bytes", "subdiv { file \"m.dat\" }", "m.dat", "100000000 1\n", true,
                        "1:1: the header announces 100000000 points and 1 face, but the rest of the file (0 characters) has room for at most 0 lines"),
                withFile("subdiv .dat header announcing more faces than the file has room for", "subdiv { file \"m.dat\" }", "m.dat",
                        "3 100000000\n0 0 0\n1 0 0\n1 1 0\n3 0 1 2\n", true,
                        "1:3: the header announces 3 points and 100000000 faces, but the rest of the file (26 characters) has room for at most 13 lines"),
                withFiles("subdiv unwrap header announcing more corners than the file has room for", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }",
                        "cube.dat", CUBE_DAT, "cube.tex", "24\n0 0\n",
                        "3:1: the file ends after 1 of the 24 corners the header announces (at 1:1)"),
                withFile("subdiv t hole with 10^8 face indices", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t hole 100000000/0/0 0\n", true,
                        "6:23: expected integer 2 of 100000000 (its counts 100000000/0/0 say 100000000 integers, 0 floats and 0 strings) of tag 'hole', found end of line"),
                withFile("subdiv t crease with 10^9 vertex indices", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t crease 1000000000/1/0 0 1 1\n", true,
                        "6:30: expected integer 4 of 1000000000 (its counts 1000000000/1/0 say 1000000000 integers, 1 float and 0 strings) of tag 'crease', found end of line"),
                withFile("subdiv unwrap not found", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT, false,
                        "1:30: unwrap file 'cube.tex' not found (looked in ${dir}/cube.tex)"),
                withFiles("subdiv unwrap with the wrong number of corners", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", "# one per corner\n20\n" + "0 0\n".repeat(20),
                        "2:1: the unwrap has 20 corners but the mesh ${dir}/cube.dat has 24 face corners (one 'u v' per corner, face after face)"),
                withFiles("subdiv points-and-faces unwrap with fewer faces than the mesh", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", "4 5\n0 0\n1 0\n1 1\n0 1\n" + "4 0 1 2 3\n".repeat(5),
                        "1:3: the unwrap has 5 faces but the mesh ${dir}/cube.dat has 6 (one texture face per face of the mesh, in the same order)"),
                withFiles("subdiv points-and-faces unwrap with a triangle for a quad", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", "4 6\n0 0\n1 0\n1 1\n0 1\n" + "4 0 1 2 3\n".repeat(2) + "3 0 1 2\n" + "4 0 1 2 3\n".repeat(3),
                        "8:1: face 2 has 3 corners but face 2 of the mesh ${dir}/cube.dat has 4 (a texture face has the corners of its mesh face, in the same order)"),
                withFiles("subdiv points-and-faces unwrap using a point it does not have", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", "4 6\n0 0\n1 0\n1 1\n0 1\n" + "4 0 1 2 3\n".repeat(5) + "4 0 1 2 4\n",
                        "11:9: face 5 uses texture point 4, out of range (the unwrap has 4 points, numbered from 0)"),
                withFiles("subdiv points-and-faces unwrap header announcing 10^8 points", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", "100000000 6\n",
                        "1:1: the header announces 100000000 texture points and 6 faces, but the rest of the file (0 characters) has room for at most 0 lines"),
                withFile("limit positions with an adaptive method", "subdiv { file \"cube.dat\"  method lazy  positions limit }", "cube.dat", CUBE_DAT, false,
                        "1:40: 'positions' needs method uniform: the adaptive methods (projected, lazy, combined) place the vertices where the refinement puts them"),
                // ---- adaptive subdivision (the file is read before the method's keys are checked) ----
                withFile("adaptive target 0", "subdiv { file \"cube.dat\"  method lazy  target 0 }", "cube.dat", CUBE_DAT, false,
                        "1:40: target edge length must be between 0.01 and 1000000 pixels, found 0.0"),
                withFile("adaptive negative target", "subdiv { file \"cube.dat\"  method projected\n  target -2 }", "cube.dat", CUBE_DAT, false,
                        "2:3: target edge length must be between 0.01 and 1000000 pixels, found -2.0"),
                withFile("adaptive target 1e-9", "subdiv { file \"cube.dat\"  method lazy  target 1e-9 }", "cube.dat", CUBE_DAT, false,
                        "1:40: target edge length must be between 0.01 and 1000000 pixels, found 1.0E-9"),
                c("adaptive target NaN", "subdiv { file \"cube.dat\"  method lazy  target NaN }",
                        "1:47: expected a number for 'target', found 'NaN' (NaN and Infinity are not allowed)"),
                c("adaptive method misspelt", "subdiv { file \"cube.dat\"  method lazzy }",
                        "1:34: expected uniform, projected, lazy or combined for 'method', found 'lazzy' (did you mean 'lazy'?)"),
                c("adaptive levels misspelt", "subdiv { file \"cube.dat\"  method lazy  levels edges }",
                        "1:47: expected rate, edge or object for 'levels', found 'edges' (did you mean 'edge'?)"),
                withFile("adaptive maxlevel 9", "subdiv { file \"cube.dat\"  method lazy  maxlevel 9 }", "cube.dat", CUBE_DAT, false,
                        "1:40: maxlevel must be between 0 and 8, found 9"),
                withFile("adaptive level and target", "subdiv { file \"cube.dat\"  method lazy  level 3\n  target 2 }", "cube.dat", CUBE_DAT, false,
                        "2:3: 'target' chooses levels from the view, but 'level' fixes one; give one of them"),
                withFile("target on a uniform subdiv", "subdiv { file \"cube.dat\"  level 2  target 1 }", "cube.dat", CUBE_DAT, false,
                        "1:36: 'target' needs an adaptive method (method projected, lazy or combined)"),
                withFile("maxlevel on a uniform subdiv", "subdiv { file \"cube.dat\"  method uniform  maxlevel 5 }", "cube.dat", CUBE_DAT, false,
                        "1:43: 'maxlevel' needs an adaptive method (method projected, lazy or combined)"),
                c("negative subdivmemory", "settings { subdivmemory -1 }", "1:12: subdivmemory must be 0 (automatic) or more mebibytes and at most 16777216, found -1.0"),
                c("absurd subdivmemory", "settings {\n  subdivmemory 1e12\n}", "2:3: subdivmemory must be 0 (automatic) or more mebibytes and at most 16777216, found 1.0E12"),
                c("subdivcache 0", "settings { subdivcache 0 }", "1:12: subdivcache must be more than 0 mebibytes and at most 16777216, found 0.0"),
                c("subdivpolicy misspelt", "settings { subdivpolicy last_two }",
                        "1:25: expected lru or last-two for 'subdivpolicy', found 'last_two' (did you mean 'last-two'?)"),
                c("subdivtarget 0", "settings { subdivtarget 0 }", "1:12: target edge length must be between 0.01 and 1000000 pixels, found 0.0"),
                // ---- CSG ----
                c("misspelt CSG statement", "diference { sphere { } box { min 0 0 0 max 1 1 1 } }", "1:1: unknown statement 'diference' (did you mean 'difference'?)"),
                c("difference with one operand", cam + "difference {\n  sphere { }\n  translate 1 0 0\n}", "2:1: difference needs at least 2 operands, found 1"),
                c("union without operands", "union { material { kd 0.5 } }", "1:1: union needs at least 2 operands, found 0"),
                c("nested intersection with one operand", "union {\n  sphere { }\n  intersection { box { min 0 0 0 max 1 1 1 } }\n}",
                        "3:3: intersection needs at least 2 operands, found 1"),
                c("triangle as an operand", "intersection {\n  sphere { }\n  triangle { vertices 0 0 0  1 0 0  0 1 0 }\n}",
                        "3:3: a triangle cannot be an intersection operand: it is not a closed solid (operands are sphere, plane, box, cylinder, "
                                + "mesh, subdiv, union, intersection or difference)"),
                c("misspelt operand", "union { shpere { } box { min 0 0 0 max 1 1 1 } }", "1:9: unknown property or operand 'shpere' in union (did you mean 'sphere'?)"),
                c("light inside a CSG block", "union { sphere { } sphere { }\nlight { position 0 5 0 }", "2:1: unknown property or operand 'light' in union (is a '}' missing to close 'union' opened at 1:1?)"),
                c("number inside a CSG block", "difference { sphere { } 2 }", "1:25: expected a property or an operand of difference or '}', found '2'"),
                c("unclosed CSG block", "union {\n  sphere { }\n  sphere { }\n", "4:1: unexpected end of file: missing '}' to close 'union' opened at 1:1"),
                c("bad value inside an operand", "difference {\n  box { min 0 0 0 max 1 1 1 }\n  sphere { radius -2 }\n}", "3:12: sphere radius must be a positive number at most 1e15, found -2.0"),
                c("CSG key given twice", "union { sphere { } sphere { } name \"a\" name \"b\" }", "1:40: 'name' given twice in union (first at 1:31)"),
                // 10,000 levels: refused at the keyword of level 1001, before the parser goes deeper.
                c("10,000 nested unions", nestedCsg(10_000, false), "1001:1: CSG nesting deeper than " + lt.spindulys.scene.Bool.MAX_NESTING
                        + " levels: this 'union' is level 1001 (union and intersection take any number of operands, so a long chain can be one block)"),
                c("10,000 nested differences and intersections", nestedCsg(10_000, true), "1001:1: CSG nesting deeper than "
                        + lt.spindulys.scene.Bool.MAX_NESTING + " levels: this 'difference' is level 1001 (union and intersection take any number"
                        + " of operands, so a long chain can be one block)"),
                withFile("open mesh as an operand", "difference {\n  box { min -1 -1 -1 max 1 1 1 }\n  mesh { file \"lid.obj\"  name \"lid\" }\n}",
                        "lid.obj", QUAD_OBJ, false, "3:3: difference operand 2 (lid) is not closed: it has 4 boundary edges"),
                withFile("open subdivision surface in a nested operand", "union {\n  sphere { }\n  intersection {\n    sphere { center 1 0 0 }\n"
                        + "    subdiv { file \"sheet.obj\"  level 1 }\n  }\n}",
                        "sheet.obj", QUAD_OBJ, false, "5:5: intersection operand 2 (subdiv) is not closed: it has 4 boundary edges"),
                // ---- errors found when the scene is built, reported at the object's statement ----
                c("zero scale on a CSG operand", "union { box { min 0 0 0 max 1 1 1 } sphere { scale 0 } }",
                        "1:46: invalid 'scale': transform is singular (a scale of zero?)"),
                c("zero scale on a CSG node", "union { box { min 0 0 0 max 1 1 1 } sphere { } scale 0 }",
                        "1:48: invalid 'scale': transform is singular (a scale of zero?)"),
                c("shrinking too far only composed with the CSG node's scale", "union {\n  box { min 0 0 0 max 1 1 1 }\n  sphere { scale 1e-10 }\n  scale 1e-10\n}",
                        "3:3: sphere: transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e20)"),
                c("named operand shrinking too far when composed", "difference {\n  box { min 0 0 0 max 1 1 1 }\n  sphere { name \"ball\"  scale 1e-10 }\n  scale 1e-10\n}",
                        "3:3: sphere 'ball': transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e20)"),
                c("nested CSG node shrinking too far when composed", "difference {\n  box { min 0 0 0 max 1 1 1 }\n  union {\n    sphere { }\n    sphere { center 1 0 0 }\n"
                        + "    scale 1e-10\n  }\n  scale 1e-10\n}", "3:3: union: transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e20)"),
                c("operand overflowing when composed", "union {\n  box { min 0 0 0 max 1 1 1 }\n  sphere { scale 1e10 }\n  scale 1e10\n}",
                        "3:3: sphere: transform scales by more than 1e15 (a matrix entry is 1e20)"),
                withFile("empty mesh as an operand", "difference {\n  box { min -1 -1 -1 max 1 1 1 }\n  mesh { file \"empty.obj\" }\n}",
                        "empty.obj", "# no faces\n", false, "3:3: difference operand 2 (mesh) is empty: it has no faces, so it has no inside"),
                // ---- undecodable bytes in the other text files, placed like the scene's own ----
                withFile("subdiv .dat that is not UTF-8", "subdiv { file \"m.dat\" }", "m.dat", bytes("3 1\n0 0 0\n1 \u00e9 0\n0 1 0\n3 0 1 2\n"), true,
                        "3:3: the mesh file is not UTF-8 text: byte 0xE9 cannot be decoded"),
                withFiles("unwrap that is not UTF-8", "subdiv { file \"cube.dat\"  uv \"cube.tex\" }", "cube.dat", CUBE_DAT,
                        "cube.tex", bytes("24\r\n0 0\r\n0 \u00ff\r\n"), "3:3: the unwrap file is not UTF-8 text: byte 0xFF cannot be decoded"),
                // ---- long tokens are cut, controls escaped: every message is one short line ----
                c("1 MB number", "sphere { radius " + run('7', MB) + " }",
                        "1:17: number '" + run('7', 40) + "...' (" + MB + " characters) is out of range"),
                c("1 MB malformed number", "sphere { radius 1" + run('x', MB) + " }",
                        "1:17: malformed number '1" + run('x', 39) + "...' (" + (MB + 1) + " characters)"),
                c("10 MB unknown property", "sphere { " + run('r', 10 * MB) + " 1 }",
                        "1:10: unknown property '" + run('r', 40) + "...' (" + 10 * MB + " characters) in sphere"),
                c("10 MB unknown statement", run('s', 10 * MB) + " { }",
                        "1:1: unknown statement '" + run('s', 40) + "...' (" + 10 * MB + " characters)"),
                c("1 MB string where a number belongs", "sphere { radius \"" + run('q', MB) + "\" }",
                        "1:17: expected a number for 'radius', found string \"" + run('q', 40) + "...\" (" + MB + " characters)"),
                c("1 MB word where a number belongs", "sphere { radius " + run('z', MB) + " }",
                        "1:17: expected a number for 'radius', found '" + run('z', 40) + "...' (" + MB + " characters)"),
                withFile("1 MB token in a .dat mesh", "subdiv { file \"m.dat\" }", "m.dat", "3 1\n0 0 0\n1 " + run('y', MB) + " 0\n0 1 0\n3 0 1 2\n", true,
                        "3:3: expected a number for point 1 y, found '" + run('y', 40) + "...' (" + MB + " characters)"),
                withFile("1 MB number in an OBJ mesh", "mesh { file \"m.obj\" }", "m.obj", "v 0 0 " + run('5', MB) + "\n", true,
                        "1:7: number " + run('5', 40) + "... (" + MB + " characters) is too large for vertex z (mesh numbers are at most 1e15 in magnitude)"),
                withFile("1 MB statement in an OBJ mesh", "mesh { file \"m.obj\" }", "m.obj", "v 0 0 0\n" + run('w', MB) + " 1\n", true,
                        "2:1: unknown OBJ statement '" + run('w', 40) + "...' (" + MB + " characters)"),
                withFile("1 MB tag name in an OBJ mesh", "subdiv { file \"m.obj\" }", "m.obj", QUAD_OBJ + "t " + run('c', MB) + " 1/0/0 0\n", true,
                        "6:3: unknown tag '" + run('c', 40) + "...' (" + MB + " characters) (known: crease, corner, hole, interpolateboundary, "
                                + "facevaryinginterpolateboundary, facevaryingpropagatecorners, creasemethod, smoothtriangles, scheme, vertexedit, edgeedit, faceedit)"),
                withFile("half a million numbers in a .dat header", "subdiv { file \"m.dat\" }", "m.dat", "1 2 " + "3 ".repeat(MB / 2) + "\n", true,
                        "1:5: expected the header 'point_count face_count' (two integers), found '1 2 " + "3 ".repeat(18) + "...' (" + (MB + 3) + " characters)"),
                c("NUL in a number", "sphere { radius 1\u0000x }", "1:17: malformed number '1\\0x'"),
                c("DEL in a string", "sphere { radius \"a\u007fb\" }", "1:17: expected a number for 'radius', found string \"a\\x7Fb\""),
                c("line separator in a number", "sphere { radius 2\u2028 }", "1:17: malformed number '2\\u2028'"),
                c("paragraph separator alone", "sphere { radius 1 }\u2029", "1:20: unexpected character U+2029"),
                c("C1 control in a word", "sphere { radius\u0085 1 }", "1:16: unexpected character U+0085 after 'radius'"),
                c("NUL in a material name", "material m\u0000n { }", "1:11: unexpected character U+0000 after 'm'"),
                c("character outside the BMP", "sphere { radius 1 } \uD83D\uDE00", "1:21: unexpected character '\uD83D\uDE00'"),
                // ---- textures ----
                c("missing texture image", "texture t {\n  image \"maps/wood.png\"\n}", "2:9: texture image 'maps/wood.png' not found (looked in ${dir}/maps/wood.png)"),
                withFile("unreadable texture image", "texture t { image \"bad.png\" }", "bad.png", "this is not a PNG\n", false,
                        "1:19: cannot read texture image 'bad.png': " + UNREADABLE_IMAGE),
                // A TGA header alone, claiming 16384 x 4097 (one row over the limit); every header byte is
                // below 0x80, so the file survives being written as UTF-8 text.
                withFile("oversized texture image", "texture t {\n  image \"huge.tga\"\n}", "huge.tga", HUGE_TGA_HEADER, false,
                        "2:9: cannot read texture image 'huge.tga': image is 16384x4097 pixels, more than the limit of 67108864 pixels (e.g. 8192x8192)"),
                c("texture without image or pattern", "texture t { scale 2 }", "1:1: texture 't' needs 'image' or 'pattern'"),
                c("texture with image and pattern", "texture t { image \"a.png\"  pattern wood }", "1:28: texture 't' has both 'image' and 'pattern': give one"),
                c("filter on a pattern", "texture t { pattern checker  filter nearest }", "1:30: 'filter' applies to image textures, not to a pattern"),
                c("unknown pattern", "texture t { pattern marbel }", "1:21: expected checker, noise, marble or wood for 'pattern', found 'marbel' (did you mean 'marble'?)"),
                c("texture name in quotes", "texture \"t\" { pattern wood }", "1:9: expected a texture name after 'texture', found string \"t\" (texture names are bare words, without quotes)"),
                c("texture defined twice", "texture t { pattern wood }\ntexture t { pattern noise }", "2:9: texture 't' is already defined at 1:1"),
                c("unknown texture in a map", "texture wood { pattern wood }\nmaterial m { map { texture wod } }", "2:28: unknown texture 'wod' (did you mean 'wood'?)"),
                c("texture used before it is defined", "material m { map { texture t } }\ntexture t { pattern wood }",
                        "1:28: unknown texture 't' (a texture must be defined before the materials that use it)"),
                c("map without a texture", "material m { map { channel bump } }", "1:14: map needs 'texture'"),
                c("unknown channel", "texture t { pattern wood }\nmaterial m { map { texture t  channel colour } }",
                        "2:39: expected diffuse, specular, reflection, transparency, emission, bump, roughness or metallic for 'channel', found 'colour'"),
                c("misspelt map key", "texture t { pattern wood }\nmaterial m { map { texture t  mapping planar  axsi 0 0 1 } }", "2:47: unknown property 'axsi' in map (did you mean 'axis'?)"),
                c("channel bound twice", "texture t { pattern wood }\nmaterial m { map { texture t }  map { texture t  channel diffuse } }", "2:33: channel diffuse already has a texture"),
                c("strength on a colour channel", "texture t { pattern wood }\nmaterial m { map { texture t  strength 2 } }", "2:31: 'strength' applies only to channel bump, not diffuse"),
                c("projection key on a uv mapping", "texture t { pattern wood }\nmaterial m { map { texture t  center 0 1 0 } }",
                        "2:31: 'center' does not apply to mapping uv (only to planar, spherical and cylindrical)"),
                c("reference along the axis", "texture t { pattern wood }\nmaterial m { map { texture t  mapping spherical  axis 0 2 0  reference 0 -1 0 } }",
                        "2:50: reference direction (0.0, -1.0, 0.0) is parallel to the axis (0.0, 2.0, 0.0)"),
                c("turbulence on a checker", "texture t { pattern checker  turbulence 2 }", "1:30: 'turbulence' applies to marble and wood, not to checker"),
                c("octaves out of range", "texture t { pattern noise  octaves 40 }", "1:28: octaves must be 1..16, got 40"),
                c("negative pattern scale", "texture t { pattern wood  scale -1 }", "1:27: scale must be positive and finite, got -1.0"),
                c("zero mapping scale", "texture t { pattern wood }\nmaterial m { map { texture t  mapping planar  scale 1 0 } }", "2:47: scale must be positive, found 1.0 0.0"),
                // Motion blur.
                c("shutter with one number", "settings { shutter 1 }", "1:22: expected 2 numbers for 'shutter', found '}'"),
                c("shutter closing before it opens", "settings { shutter 1 0 }", "1:12: shutter must close after it opens, found open 1.0 and close 0.0"),
                c("timesteps zero", "settings { timesteps 0 }", "1:12: timesteps must be between 1 and 65536, found 0"),
                c("timesteps not dividing samples", "settings { samples 6  timesteps 4 }",
                        "1:23: samples 6 is not a multiple of timesteps 4 (each time step renders samples / timesteps per pixel)"),
                c("motion block without a brace", "sphere { motion translate 1 0 0 }", "1:17: expected '{' after 'motion', found 'translate'"),
                c("misspelt motion key", "sphere { motion { translte 1 0 0 } }", "1:19: unknown property 'translte' in motion (did you mean 'translate'?)"),
                c("motion translate and direction", "sphere { motion { translate 1 0 0  direction 1 0 0  speed 2 } }",
                        "1:36: motion has both 'translate' and 'direction': give the end translation, or direction and speed"),
                c("motion direction without speed", "sphere { motion { direction 1 0 0 } }", "1:19: 'direction' needs 'speed' (units per unit of shutter time)"),
                c("motion speed without direction", "sphere { motion { speed 1 } }", "1:19: 'speed' needs 'direction'"),
                c("motion that does not move", "sphere { motion { start 0.5 } }",
                        "1:10: motion needs translate, direction and speed, rotate or scale: without them the object does not move"),
                c("motion zero direction", "sphere { motion { direction 0 0 0  speed 1 } }", "1:19: motion direction has zero length"),
                c("motion negative scale", "box { min 0 0 0  max 1 1 1  motion { scale -1 } }", "1:38: motion scale must be positive, found -1.0 -1.0 -1.0"),
                c("motion rotate without an axis", "sphere { motion { rotate 90 } }", "1:29: expected an axis (x, y, z or 3 numbers) and an angle for 'rotate', found '}'"),
                c("motion finish before start", "sphere { motion { translate 1 0 0  start 0.6  finish 0.2 } }",
                        "1:36: motion finish must be after its start, found start 0.6 and finish 0.2"),
                c("motion start after the shutter closes", "sphere { motion { translate 1 0 0  start 2 } }\nsettings { shutter 0 1 }",
                        "1:36: motion finish must be after its start, found start 2.0 and finish 1.0 (finish is the shutter close time)"),
                c("motion given twice", "sphere { motion { translate 1 0 0 }  motion { translate 0 1 0 } }", "1:38: 'motion' given twice in sphere (first at 1:10)"),
                c("motion translate given twice", "sphere { motion { translate 1 0 0  translate 0 1 0 } }", "1:36: 'translate' given twice in motion (first at 1:19)"),
                // Animation: keys, turntables and the animation statement (docs/scene-format.md "Animation").
                c("keys without an animation", "sphere { keys { key 1 { } } }",
                        "1:10: 'keys' needs an animation statement before it (such as animation { frames 1 48  fps 24 }): key frames are read on its clock"),
                c("keys out of order", "animation { frames 1 9 }\nsphere { keys { key 5 { } key 3 { } } }",
                        "2:31: key frame 3 is not after the previous key's frame 5 (at 2:21): keys must be in increasing frame order, each frame once"),
                c("keys at one frame twice", "animation { frames 1 9 }\nsphere { keys { key 4 { } key 4.0 { } } }",
                        "2:31: key frame 4 is not after the previous key's frame 4 (at 2:21): keys must be in increasing frame order, each frame once"),
                c("keys without a key", "animation { frames 1 9 }\nsphere { keys { } }", "2:10: keys needs at least one 'key FRAME { translate ... rotate ... scale ... }'"),
                c("misspelt key pose key", "animation { frames 1 9 }\nsphere { keys { key 1 { rotat 0 90 0 } } }",
                        "2:25: unknown property 'rotat' in key (did you mean 'rotate'?)"),
                c("keys and a turntable", "animation { frames 1 9 }\nbox { min 0 0 0  max 1 1 1  turntable { }  keys { key 1 { } } }",
                        "2:44: 'keys' and 'turntable' (at 2:29) exclude each other: a turntable is keys of its own"),
                c("camera keys that scale", "animation { frames 1 9 }\ncamera { eye 0 0 -5  lookat 0 0 0  keys { key 1 { scale 2 } } }",
                        "2:36: a camera's keys may translate and rotate it but not scale it"),
                c("animation frames backwards", "animation { frames 9 1 }", "1:13: last frame must be between the first (9) and 9999999, found 1"),
                c("animation fps near 0", "animation { frames 1 9  fps 1e-320 }", "1:25: fps must be between 0.001 and 1000, found 1.0E-320"),
                c("animation fps near 0 at frame 0", "animation { frames 0 0  fps 1e-300 }", "1:25: fps must be between 0.001 and 1000, found 1.0E-300"),
                c("animation fps 0", "animation { frames 1 9  fps 0 }", "1:25: fps must be between 0.001 and 1000, found 0.0"),
                c("animation fps over 1000", "animation { frames 1 9  fps 1001 }", "1:25: fps must be between 0.001 and 1000, found 1001.0"),
                c("animation shutter over 360", "animation { frames 1 9  shutter 361 }", "1:25: shutter angle must be between 0 and 360 degrees, found 361.0"),
                c("animation last frame too large", "animation { frames 1 10000000 }", "1:13: last frame must be between the first (1) and 9999999, found 10000000"),
                c("animation shutter with a settings shutter", "settings { shutter 0 1 }\nanimation { frames 1 9 }",
                        "1:12: 'shutter' in settings does not combine with the animation at 2:1: each frame's shutter is set by the animation's shutter angle"),
                // Ranges that keep every pixel finite (lt.spindulys.math.Ranges, docs/scene-format.md "Ranges of numbers").
                c("light intensity 1e308", "light { position 0 5 0  intensity 1e308 }", "1:35: number '1e308' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("light intensity just over 1e15", "light { position 0 5 0  intensity 1.0000001e15 }", "1:35: number '1.0000001e15' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("light color over 100", "light { position 0 5 0  color 1 101 1 }", "1:25: light color must have components between 0 and 100, found (1.0, 101.0, 1.0)"),
                c("lights' total over 1e20", "light { position 0 5 0  color 100  intensity 1e15 }\n".repeat(1000) + "light { position 0 5 0  color 100  intensity 1e15 }",
                        "1001:36: light intensity 1.0E15 brings the lights' total (intensity times the largest colour component, summed over the lights) to 1.001E20, more than 1e20"),
                c("material color over 100", "material m { color 200 }", "1:14: color must have components between 0 and 100, found (200.0, 200.0, 200.0)"),
                c("ka over 10", "material m { ka 11 }", "1:14: ka must be between 0 and 10, found 11.0"),
                c("kd over 10", "sphere { material { kd 1e3 } }", "1:21: kd must be between 0 and 10, found 1000.0"),
                c("ks over 10", "material m { ks 10.5 }", "1:14: ks must be between 0 and 10, found 10.5"),
                c("shininess over 1e6", "material m { shininess 1e7 }", "1:14: shininess must be between 0 and 1e6, found 1.0E7"),
                c("kr over 1", "material m { kr 1.5 }", "1:14: kr must be between 0 and 1, found 1.5"),
                c("kt over 1", "material m { kt 2 }", "1:14: kt must be between 0 and 1, found 2.0"),
                c("kr + kt over 1", "material m {\n  kt 0.6\n  kr 0.6\n}", "3:3: kr + kt must be at most 1, found kr 0.6 + kt 0.6 = 1.2"),
                c("filter over 1", "material m { filter 1 2 1 }", "1:14: filter must have components between 0 and 1, found (1.0, 2.0, 1.0)"),
                c("beta over 1e15", "material m { beta 1e16 }", "1:19: number '1e16' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("ambient over 100", "settings { ambient 1000 }", "1:12: ambient must have components between 0 and 100, found (1000.0, 1000.0, 1000.0)"),
                c("background over 100", "settings { background 0 0 1e9 }", "1:12: background must have components between 0 and 100, found (0.0, 0.0, 1.0E9)"),
                c("pattern colour over 100", "texture t { pattern checker  color1 0 0 -101 }", "1:30: color1 must have components between -100 and 100, found (0.0, 0.0, -101.0)"),
                c("bump strength over 1e15", "texture t { pattern noise }\nmaterial m { map { texture t  channel bump  strength 1e300 } }", "2:54: number '1e300' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("sphere radius 1e200", "sphere { radius 1e200 }", "1:17: number '1e200' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("coordinate 1e300", "box { min 0 0 0  max 1 1e300 1 }", "1:24: number '1e300' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("camera far away", "camera { eye 0 0 -2e15 }", "1:18: number '-2e15' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("scale factor over 1e15", "sphere { scale 1e16 }", "1:16: number '1e16' is out of range: scene numbers are at most 1e15 in magnitude"),
                c("scales composing over 1e15", "sphere {\n  scale 1e10\n  scale 1e10\n}", "3:3: invalid 'scale': transform scales by more than 1e15 (a matrix entry is 1e20)"),
                c("scale factor under 1e-15", "sphere { scale 1 1e-16 1 }", "1:10: invalid 'scale': transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e16)"),
                withFile("OBJ vertex over 1e15", "mesh { file \"m.obj\" }", "m.obj", "v 0 0 0\nv 1 0 0\nv 0 2e15 0\nf 1 2 3\n", true,
                        "3:5: number 2e15 is too large for vertex y (mesh numbers are at most 1e15 in magnitude)"),
                withFile("OBJ normal over 1e15", "mesh { file \"m.obj\" }", "m.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 -1e16\nf 1//1 2//1 3//1\n", true,
                        "4:8: number -1e16 is too large for normal z (mesh numbers are at most 1e15 in magnitude)"),
                withFile("subdiv .dat point over 1e15", "subdiv { file \"m.dat\" }", "m.dat", "4 1\n0 0 0\n1 0 0\n1 1e300 0\n0 1 0\n4 0 1 2 3\n", true,
                        "4:3: number 1e300 is too large for point 2 y (mesh numbers are at most 1e15 in magnitude)"),
                // OBJ materials (mtllib, usemtl, .mtl files, the scene's usemtl key).
                new Case("OBJ mtllib not found", "mesh { file \"m.obj\" }", "4:8: material library 'none.mtl' not found (looked in ${dir}/none.mtl; a 'material' key on the object replaces the file's materials)",
                        Map.of("m.obj", TRI_OBJ + "mtllib none.mtl\nusemtl red\nf 1 2 3\n"), "m.obj"),
                new Case("OBJ usemtl that no library defines", "subdiv { file \"m.obj\"  level 1 }",
                        "7:8: no material 'blue': no material library it names (m.mtl) defines it, and the scene gives none"
                                + " (write usemtl \"blue\" and a material in the 'subdiv' block at 1:1)",
                        Map.of("m.obj", TRI_OBJ + "mtllib m.mtl\nusemtl red\nf 1 2 3\nusemtl blue\nf 1 3 2\n", "m.mtl", "newmtl red\nKd 1 0 0\n"), "m.obj"),
                new Case("OBJ usemtl without any mtllib", "mesh { file \"m.obj\" }",
                        "4:8: no material 'red': the file names no material library (mtllib), and the scene gives none"
                                + " (write usemtl \"red\" and a material in the 'mesh' block at 1:1)",
                        Map.of("m.obj", TRI_OBJ + "usemtl red\nf 1 2 3\n"), "m.obj"),
                withFiles(".mtl unknown statement", "mesh { file \"m.obj\" }", "m.obj", TRI_OBJ + "mtllib m.mtl\nusemtl red\nf 1 2 3\n",
                        "m.mtl", "newmtl red\nKd 1 0 0\nKf 1\n",
                        "3:1: unknown material statement 'Kf' (did you mean 'Kd'?) (supported: newmtl, Kd, Ka, Ks, Ns, d, Tr, Tf, Ni, Ke, illum, map_Kd, map_Ks, map_d, map_Bump, bump, Pr, Pm, map_Pr, map_Pm)"),
                withFiles(".mtl bad number", "mesh { file \"m.obj\" }", "m.obj", TRI_OBJ + "mtllib m.mtl\nusemtl red\nf 1 2 3\n",
                        "m.mtl", "newmtl red\nNs 1e\n", "2:4: expected a number for 'Ns', found '1e'"),
                withFiles(".mtl texture not found", "mesh { file \"m.obj\" }", "m.obj", TRI_OBJ + "mtllib m.mtl\nusemtl red\nf 1 2 3\n",
                        "m.mtl", "newmtl red\nmap_Kd -s 2 red.png\n", "2:13: texture image 'red.png' not found (looked in ${dir}/red.png)"),
                withFiles(".mtl texture option not supported", "mesh { file \"m.obj\" }", "m.obj", TRI_OBJ + "mtllib m.mtl\nusemtl red\nf 1 2 3\n",
                        "m.mtl", "newmtl red\nmap_Kd -texres 512 red.png\n", "2:8: texture option '-texres' is not supported (supported: -o, -s, -clamp)"),
                withFile("scene usemtl for a name the OBJ lacks", "mesh { file \"m.obj\"  usemtl \"blue\" { color 0 0 1 } }", "m.obj",
                        TRI_OBJ + "usemtl red\nf 1 2 3\n", false, "1:29: usemtl 'blue': 'm.obj' has no usemtl of that name (its names: red)"),
                withFile("scene usemtl twice", "mesh { file \"m.obj\"  usemtl \"red\" { color 1 0 0 }\n  usemtl \"red\" { color 0 0 1 } }", "m.obj",
                        TRI_OBJ + "usemtl red\nf 1 2 3\n", false, "2:10: usemtl 'red' given twice (first at 1:29)"),
                withFile("scene usemtl without a material", "mesh { file \"m.obj\"  usemtl \"red\" }", "m.obj",
                        TRI_OBJ + "usemtl red\nf 1 2 3\n", false, "1:35: expected a material name or '{' after 'usemtl NAME', found '}'"),
                withFile("scene usemtl on a mesh without usemtl", "subdiv { file \"m.dat\"  usemtl \"red\" { } }", "m.dat", CUBE_DAT, false,
                        "1:31: usemtl 'red': 'm.dat' has no usemtl statements"));
    }
}
