package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Path;
import java.util.Locale;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.io.ObjReader;
import lt.spindulys.io.ObjWriter;
import lt.spindulys.limits.MessageText;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;

/**
 * {@code render subdivide IN.(obj|dat) --level N [--limit] [--uv IN.tex] -o OUT.obj}: refines a
 * control mesh by Catmull-Clark and writes the refined mesh as an OBJ file, atomically.
 */
final class SubdivideCommand {
    static final String USAGE = """
            usage: render subdivide MESH.obj|MESH.dat --level N -o OUT.obj [--limit] [--uv UNWRAP.tex] [--debug]
                   render subdivide --help

            Refines a control mesh by Catmull-Clark subdivision (OpenSubdiv's rules; the t tags of an
            OBJ file give creases, corners, holes and options) and writes the refined mesh as OBJ:
            v positions, vt face-varying UVs (when the mesh has them), f quads; holes are left out.
            The mesh formats are described in docs/mesh-formats.md.

              --level N          refinement level, 0 to 8 (required)
              -o, --output OUT   the .obj file to write (required); written atomically
              --limit            write limit-surface positions, and vn limit normals
              --uv UNWRAP.tex    face-varying UVs from a Workframe unwrap (one u v per face corner)
              --debug            stack traces on errors
            Exit status: 0 success, 2 bad usage or bad input, 1 failure while writing.""";

    /**
     * Heap refinement needs per refined face at its peak (the levels' meshes, the last one kept),
     * for the refined mesh alone: no triangles or acceleration structure are built here. The
     * measured peak with a margin above it; the measurement is in docs/performance.md (heap per
     * refined face).
     */
    static final long BYTES_PER_FACE = 176;

    /** Added per face by --limit: limit positions and normals, three doubles each per vertex. */
    static final long LIMIT_BYTES_PER_FACE = 64;

    private Path input, output, uv;
    private Integer level;
    private boolean limit;

    /** Parses the arguments after "subdivide" (and without --debug). */
    SubdivideCommand(String[] args) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "-o", "--output" -> output = Path.of(value(args, ++i, a));
                case "--uv" -> uv = Path.of(value(args, ++i, a));
                case "--level" -> level = levelValue(value(args, ++i, a));
                case "--limit" -> limit = true;
                default -> {
                    if (a.startsWith("-") && a.length() > 1) throw new UsageException("unknown option '" + a + "' for subdivide (see render subdivide --help)");
                    if (input != null) throw new UsageException("more than one mesh given: '" + input + "' and '" + a + "'");
                    input = Path.of(a);
                }
            }
        }
        if (input == null) throw new UsageException("no mesh given to subdivide (see render subdivide --help)");
        String ext = extension(input);
        if (!ext.equals("obj") && !ext.equals("dat")) {
            throw new UsageException("the mesh to subdivide must be an .obj or a .dat file, found '" + input + "'");
        }
        if (level == null) throw new UsageException("subdivide needs --level N (see render subdivide --help)");
        if (output == null) throw new UsageException("subdivide needs an output file: -o OUT.obj (see render subdivide --help)");
        if (!extension(output).equals("obj")) throw new UsageException("the output of subdivide must be an .obj file, found '" + output + "'");
    }

    /** Runs the command; returns the exit status. Bad input surfaces as exceptions handled by {@link Main}. */
    int run(PrintStream out, PrintStream err) throws IOException, UsageException {
        try {
            AtomicFile.checkWritable(output); // fail before the work, not after
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
        String name = input.toString();
        SubdivInput in = extension(input).equals("obj") ? ObjReader.readSubdiv(input) : SubdivInput.of(WorkframeReader.readMesh(input));
        if (uv != null) in = in.withCornerUvs(WorkframeReader.readUnwrap(uv, in.mesh()));
        try {
            SubdivisionSurface.checkLevel(level, in.refinedFaceCount(level), limit ? BYTES_PER_FACE + LIMIT_BYTES_PER_FACE : BYTES_PER_FACE);
        } catch (IllegalArgumentException e) {
            // The level is the option's: the mesh is fine, the level asked of it is too deep.
            throw new UsageException("--level " + level + ": " + name + ": " + e.getMessage());
        }
        for (String tag : in.tags().ignored()) {
            err.println(MessageText.escape(name + ": note: tag '" + tag + "' is ignored (OpenSubdiv's Far does not apply it either)"));
        }
        ControlMesh control = in.toControlMesh();
        RefinedMesh refined = CatmullClark.refine(control, level);
        String comment = "Catmull-Clark subdivision of " + input.getFileName() + " at level " + level
                + (limit ? ", limit positions and normals" : "") + " (spindulys " + Main.version() + ")\n"
                + refined.vertexCount() + " vertices, " + refined.faceCount() + " faces";
        AtomicFile.write(output, os -> ObjWriter.write(refined, limit, comment, os));
        return 0;
    }

    private static Integer levelValue(String v) throws UsageException {
        try {
            return SubdivisionSurface.checkLevel(Integer.parseInt(v));
        } catch (NumberFormatException e) {
            throw new UsageException("--level expects a whole number, found '" + v + "'");
        } catch (IllegalArgumentException e) {
            throw new UsageException("--level must be between 0 and " + SubdivisionSurface.MAX_LEVEL + ", found " + v);
        }
    }

    private static String value(String[] args, int i, String option) throws UsageException {
        if (i >= args.length) throw new UsageException("option " + option + " needs a value");
        return args[i];
    }

    private static String extension(Path p) {
        String n = p.getFileName() == null ? "" : p.getFileName().toString();
        int dot = n.lastIndexOf('.');
        return dot < 0 ? "" : n.substring(dot + 1).toLowerCase(Locale.ROOT);
    }
}
