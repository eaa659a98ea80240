package lt.spindulys.cli;

import java.io.IOException;
import java.io.PrintStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.files.FileNames;
import lt.spindulys.io.AssetRoots;
import lt.spindulys.io.ObjReader;
import lt.spindulys.io.ObjWriter;
import lt.spindulys.limits.MessageText;
import lt.spindulys.io.SceneParser;
import lt.spindulys.io.WorkframeReader;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.InputFile;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;

/**
 * {@code render subdivide IN.(obj|dat) [--scheme catmark|loop|bilinear] --level N [--limit] [--uv IN.tex] -o OUT.obj}:
 * refines a control mesh with its scheme (the OBJ file's {@code t scheme} tag, else Catmull-Clark;
 * {@code --scheme} overrides it) and writes the refined mesh as an OBJ file, atomically; with
 * {@code --scene SCENE.dat} instead of {@code --level}, writes the tessellation that scene renders
 * the mesh with (adaptive: per-edge levels from its camera, stitched and welded).
 */
final class SubdivideCommand {
    static final String USAGE = """
            usage: render subdivide MESH.obj|MESH.dat --level N -o OUT.obj [--scheme catmark|loop|bilinear] [--limit] [--uv UNWRAP.tex] [--debug]
                   render subdivide MESH.obj|MESH.dat --scene SCENE.dat -o OUT.obj [--assets-root DIR]... [--debug]
                   render subdivide --help

            Refines a control mesh by Catmull-Clark, Loop or bilinear subdivision (OpenSubdiv's rules;
            the t tags of an OBJ file give creases, corners, holes, options and the scheme) and writes
            the refined mesh as OBJ: v positions, vt face-varying UVs (when the mesh has them), f quads
            (triangles for Loop); holes are left out.
            With --scene, writes the tessellation that scene renders the mesh with instead: the
            scene's subdiv statement naming MESH chooses the method, levels (per edge, from its
            camera, for an adaptive method) and options; the patches are stitched and welded, so
            the triangles (v, vt, vn, f v/vt/vn) are crack-free. A uniform subdiv statement gives
            its uniform refinement (at its limit positions with 'positions limit'). The mesh
            formats are described in docs/mesh-formats.md.

              --level N          refinement level, 0 to 8 (this or --scene is required)
              --scheme S         catmark, loop (triangles only) or bilinear; overrides the OBJ file's
                                 t scheme tag (default: the file's, else catmark; with --level)
              --scene SCENE.dat  the tessellation SCENE.dat would render MESH with
              -o, --output OUT   the .obj file to write (required); written atomically
              --limit            write limit-surface positions, and vn limit normals (with --level)
              --uv UNWRAP.tex    face-varying UVs from a Workframe unwrap (points and faces, or one u v per
                                 face corner; with --level)
              --assets-root DIR  with --scene: the scene reads only inside DIR, as render's option (repeatable;
                                 SPINDULYS_ASSETS_ROOT applies too)
              --debug            stack traces on errors
            The output may not be one of the files read (the mesh, the unwrap, the scene and what it names).
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

    private Path input, output, uv, scene;
    /** The --assets-root folders, in order. */
    private final List<Path> assetFolders = new ArrayList<>();
    /** What the --scene may read: --assets-root and SPINDULYS_ASSETS_ROOT together. */
    private final AssetRoots assetRoots;
    private Integer level;
    private boolean limit;
    /** The --scheme given, or null for the file's own. */
    private SubdivOptions.Scheme scheme;

    /** Parses the arguments after "subdivide" (and without --debug), with the process's environment. */
    SubdivideCommand(String[] args) throws UsageException {
        this(args, System.getenv());
    }

    /** Parses the arguments after "subdivide" (and without --debug); {@code env} gives SPINDULYS_ASSETS_ROOT. */
    SubdivideCommand(String[] args, Map<String, String> env) throws UsageException {
        for (int i = 0; i < args.length; i++) {
            String a = args[i];
            switch (a) {
                case "-o", "--output" -> output = Path.of(OptionValues.value(args, ++i, a));
                case "--uv" -> uv = Path.of(OptionValues.value(args, ++i, a));
                case "--level" -> level = levelValue(OptionValues.value(args, ++i, a));
                case "--limit" -> limit = true;
                case "--scene" -> scene = Path.of(OptionValues.value(args, ++i, a));
                case "--scheme" -> scheme = schemeValue(OptionValues.value(args, ++i, a));
                case "--assets-root" -> assetFolders.add(RenderCommand.pathValue(args, ++i, a));
                default -> {
                    if (a.startsWith("-") && a.length() > 1) throw new UsageException("unknown option '" + a + "' for subdivide (see render subdivide --help)");
                    if (input != null) throw new UsageException("more than one mesh given: '" + input + "' and '" + a + "'");
                    input = Path.of(a);
                }
            }
        }
        if (input == null) throw new UsageException("no mesh given to subdivide (see render subdivide --help)");
        String ext = FileNames.extension(input);
        if (!ext.equals("obj") && !ext.equals("dat")) {
            throw new UsageException("the mesh to subdivide must be an .obj or a .dat file, found '" + input + "'");
        }
        if (scene != null) {
            if (level != null) throw new UsageException("--level and --scene exclude each other: the scene's subdiv statement chooses the levels");
            if (limit) throw new UsageException("--limit goes with --level, not --scene (the scene's tessellation is written as it renders it)");
            if (uv != null) throw new UsageException("--uv goes with --level, not --scene (the scene's subdiv statement names its unwrap)");
            if (scheme != null) throw new UsageException("--scheme goes with --level, not --scene (the scene's subdiv statement chooses the scheme)");
        } else if (level == null) {
            throw new UsageException("subdivide needs --level N or --scene SCENE.dat (see render subdivide --help)");
        } else if (!assetFolders.isEmpty()) {
            throw new UsageException("--assets-root goes with --scene: it confines what a scene reads");
        }
        if (output == null) throw new UsageException("subdivide needs an output file: -o OUT.obj (see render subdivide --help)");
        if (FileNames.isOnlyExtension(output)) throw new UsageException(FileNames.onlyExtensionMessage(output));
        if (!FileNames.extension(output).equals("obj")) throw new UsageException("the output of subdivide must be an .obj file, found '" + output + "'");
        assetRoots = RenderCommand.assetRoots(assetFolders, env);
        checkNotInput(givenInputs());
    }

    /** The files named on the command line that the run reads: the mesh, the unwrap, the scene. */
    private List<InputFile> givenInputs() {
        List<InputFile> in = new ArrayList<>();
        in.add(new InputFile(input, "mesh", null));
        if (uv != null) in.add(new InputFile(uv, "unwrap", null));
        if (scene != null) in.add(new InputFile(scene, "scene file", null));
        return in;
    }

    /** Refuses an output that is one of {@code inputs}: writing it would replace what was read. */
    private void checkNotInput(List<InputFile> inputs) throws UsageException {
        try {
            InputFile.checkOutput(output, inputs);
        } catch (InputFile.OutputIsInputException e) {
            throw new UsageException(e.getMessage());
        }
    }

    /** Runs the command; returns the exit status. Bad input surfaces as exceptions handled by {@link Main}. */
    int run(PrintStream out, PrintStream err) throws IOException, UsageException {
        try {
            AtomicFile.checkWritable(output); // fail before the work, not after
        } catch (IOException e) {
            throw new UsageException(e.getMessage());
        }
        if (scene != null) return runScene(err);
        String name = input.toString();
        SubdivInput in = FileNames.extension(input).equals("obj") ? ObjReader.readSubdiv(input) : SubdivInput.of(WorkframeReader.readMesh(input));
        if (uv != null) in = WorkframeReader.readTex(uv, in.mesh()).applyTo(in);
        if (scheme != null) in = in.withOptions(in.options().withScheme(scheme));
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
        RefinedMesh refined = Subdivision.refine(control, level);
        String comment = schemeName(control.options().scheme()) + " subdivision of " + input.getFileName() + " at level " + level
                + (limit ? ", limit positions and normals" : "") + " (spindulys " + Main.version() + ")\n"
                + refined.vertexCount() + " vertices, " + refined.faceCount() + " faces";
        AtomicFile.write(output, os -> ObjWriter.write(refined, limit, comment, os));
        return 0;
    }

    /**
     * --scene: parses and builds the scene as a render would, finds its subdiv statements whose
     * control mesh is the input file, and writes the tessellation the first of them renders with
     * (adaptive statements before uniform ones; a note names the others when their options differ,
     * since they do not share one tessellation).
     */
    private int runScene(PrintStream err) throws IOException, UsageException {
        String problem = InputFiles.problem(scene);
        if (problem != null) throw new RenderCommand.NoSuchFileException(scene, problem);
        problem = InputFiles.problem(input);
        if (problem != null) throw new UsageException("mesh " + input + " " + problem);
        SceneBuilder parsed = SceneParser.parse(scene, assetRoots);
        checkNotInput(parsed.inputFiles()); // before the build, which may take long
        Scene built = parsed.build();
        List<AdaptiveSubdivisionSurface> adaptive = new ArrayList<>();
        List<SubdivisionSurface> uniform = new ArrayList<>();
        List<String> others = new ArrayList<>();
        collect(built.objects(), adaptive, uniform, others);
        String note = null;
        if (!adaptive.isEmpty()) {
            AdaptiveSubdivisionSurface first = adaptive.get(0);
            List<String> differ = new ArrayList<>();
            for (AdaptiveSubdivisionSurface s : adaptive) if (!sameTessellation(first, s)) differ.add(where(s));
            if (!differ.isEmpty()) {
                note = "note: " + adaptive.size() + " subdiv statements of " + scene + " refine " + input + " with different options; writing the tessellation of the first ("
                        + where(first) + "), not of " + String.join(", ", differ);
            }
            MeshData m = first.tessellation();
            int[] edgeLevels = first.edgeLevels();
            String comment = "tessellation of " + input.getFileName() + " as " + scene.getFileName() + " renders it (" + where(first) + ", method "
                    + first.method().word() + ") (spindulys " + Main.version() + ")\n"
                    + "control edges per level: " + histogram(edgeLevels) + "\n"
                    + m.vertexCount() + " vertices, " + m.faceCount() + " triangles, welded: crack-free";
            AtomicFile.write(output, os -> ObjWriter.write(m, comment, os));
        } else if (!uniform.isEmpty()) {
            SubdivisionSurface first = uniform.get(0);
            List<String> differ = new ArrayList<>();
            for (SubdivisionSurface s : uniform) if (s.refined() != first.refined() || s.positions() != first.positions()) differ.add(where(s));
            if (!differ.isEmpty()) {
                note = "note: " + uniform.size() + " subdiv statements of " + scene + " refine " + input + " differently; writing the first's ("
                        + where(first) + "), not " + String.join(", ", differ);
            }
            RefinedMesh refined = first.refined();
            // positions limit renders the limit positions: written with the limit normals, as --limit writes them.
            boolean limitPositions = first.positions() == SubdivisionSurface.Positions.LIMIT;
            String comment = schemeName(refined.controlMesh().options().scheme()) + " subdivision of " + input.getFileName() + " at level " + first.level() + " as " + scene.getFileName()
                    + " renders it (" + where(first) + ", method uniform" + (limitPositions ? ", positions " + first.positions().word() + ": limit positions and normals" : "")
                    + ") (spindulys " + Main.version() + ")\n"
                    + refined.vertexCount() + " vertices, " + refined.faceCount() + " faces";
            AtomicFile.write(output, os -> ObjWriter.write(refined, limitPositions, comment, os));
        } else {
            throw new UsageException(scene + " has no subdiv statement whose file is " + input
                    + (others.isEmpty() ? " (it has none)" : " (its subdiv files: " + String.join(", ", others) + ")"));
        }
        if (note != null) err.println(MessageText.escape(note));
        return 0;
    }

    /** The subdiv surfaces among {@code objects} (CSG operands too) whose control mesh is the input file; the others' files. */
    private void collect(List<GObject> objects, List<AdaptiveSubdivisionSurface> adaptive, List<SubdivisionSurface> uniform, List<String> others) {
        for (GObject o : objects) {
            if (o instanceof Bool b) {
                collect(b.operands(), adaptive, uniform, others);
            } else if (o instanceof AdaptiveSubdivisionSurface a) {
                if (isInput(a.control().source())) adaptive.add(a);
                else others.add(a.control().source());
            } else if (o instanceof SubdivisionSurface u) {
                if (isInput(u.refined().controlMesh().source())) uniform.add(u);
                else others.add(u.refined().controlMesh().source());
            }
        }
    }

    /** True if the parser's path of a control mesh (absolute, normalised) is the input file. */
    private boolean isInput(String source) {
        if (source == null) return false;
        Path p = Path.of(source);
        if (p.equals(input.toAbsolutePath().normalize())) return true;
        try {
            return Files.isSameFile(p, input);
        } catch (IOException e) {
            return false;
        }
    }

    /** True if two placements use one tessellation: the scene shares it when the geometry and every option agree. */
    private static boolean sameTessellation(AdaptiveSubdivisionSurface a, AdaptiveSubdivisionSurface b) {
        return a.refiner() == b.refiner() && a.method() == b.method() && a.isSmooth() == b.isSmooth() && a.fixedLevel() == b.fixedLevel()
                && a.maxLevel() == b.maxLevel() && a.target() == b.target() && a.levels() == b.levels();
    }

    private static String where(GObject o) { return o.source() != null ? o.source() : o.name(); }

    /** "level 3: 12, level 4: 40": how many control edges have each level. */
    private static String histogram(int[] levels) {
        java.util.TreeMap<Integer, Integer> h = new java.util.TreeMap<>();
        for (int l : levels) h.merge(l, 1, Integer::sum);
        StringBuilder b = new StringBuilder();
        h.forEach((l, n) -> b.append(b.length() == 0 ? "" : ", ").append("level ").append(l).append(": ").append(n));
        return b.toString();
    }

    /** The name of a scheme in the output's first comment line. */
    static String schemeName(SubdivOptions.Scheme s) {
        return switch (s) {
            case CATMARK -> "Catmull-Clark";
            case LOOP -> "Loop";
            case BILINEAR -> "bilinear";
        };
    }

    private static SubdivOptions.Scheme schemeValue(String v) throws UsageException {
        SubdivOptions.Scheme s = SubdivOptions.Scheme.ofKeyword(v);
        if (s == null) throw new UsageException("--scheme expects catmark, loop or bilinear, found '" + v + "'");
        return s;
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
}
