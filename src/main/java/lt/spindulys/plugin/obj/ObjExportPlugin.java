package lt.spindulys.plugin.obj;

import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.HashSet;
import java.util.List;
import java.util.Locale;
import java.util.Map;
import java.util.Set;
import java.util.concurrent.CancellationException;
import java.util.function.DoubleConsumer;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.files.FileNames;
import lt.spindulys.io.ObjWriter;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.subdiv.Subdivision;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.RefinedMesh;

/**
 * The second output plugin (id {@code obj}): writes the displayed surfaces as Wavefront OBJ, so
 * that a surface shaped in a viewer can be taken to another tool, or to a scene file's
 * {@code subdiv} statement.
 *
 * <p>Options: {@value #EXPORT} chooses what is written:
 * <ul>
 *   <li>{@value #CONTROL}: each control mesh with its OpenSubdiv tags (creases, corners, holes, the
 *       scheme and its options) and face-varying uvs, by {@link ObjWriter#write(ControlMesh, String, String,
 *       java.io.OutputStream)}; reading the file back with {@link lt.spindulys.io.ObjReader#readSubdiv}
 *       gives an equal control mesh. Tags and scheme options belong to a whole OBJ file (their
 *       indices count through the file and a reader applies one set of options), so one surface
 *       goes to the chosen file, and several go one per file beside it, named after the chosen
 *       file and the surface: {@code out.obj} with surfaces {@code cube.obj} and {@code torus}
 *       gives {@code out-cube.obj} and {@code out-torus.obj} (the chosen file's name comes first so
 *       that a surface never overwrites the mesh file it was opened from).</li>
 *   <li>{@value #REFINED}: each surface refined as many times as the host shows it (its
 *       {@link DisplayedSurface#level()}; the control mesh for {@link DisplayedSurface.Scheme#NONE}),
 *       hole faces left out, all in the chosen file, one {@code o NAME} object per surface.</li>
 *   <li>{@value #LIMIT}: as {@value #REFINED}, with every vertex moved to the limit surface and
 *       the limit normals as {@code vn}.</li>
 * </ul>
 * and {@code surface.N.export} (true or false, one per surface, in a group named after it) whether
 * surface N is written; at least one must be.
 *
 * <p>Every file is written atomically ({@link AtomicFile#writeAll}): a failed or cancelled run
 * leaves no new file and every old one as it was. The output's folder is tried before any work,
 * so an unwritable path fails at once with one line.
 */
public final class ObjExportPlugin implements OutputPlugin {
    /** The option choosing what is written. */
    public static final String EXPORT = "export";
    /** {@link #EXPORT}: the control meshes with their tags. */
    public static final String CONTROL = "control mesh";
    /** {@link #EXPORT}: the surfaces refined at the host's levels. */
    public static final String REFINED = "refined";
    /** {@link #EXPORT}: the refined vertices on the limit surface, with limit normals. */
    public static final String LIMIT = "limit surface";

    /**
     * Heap per refined face while refining, and added for limit positions and normals: the figures
     * {@code render subdivide} checks with, measured for refinement alone (docs/performance.md,
     * "Heap per refined face"); a scene's surface needs more, for its triangles and structure.
     */
    static final long BYTES_PER_FACE = 176, LIMIT_BYTES_PER_FACE = 64;

    /** A public no-argument constructor, for {@link java.util.ServiceLoader}. */
    public ObjExportPlugin() {}

    @Override public String id() { return "obj"; }

    @Override public String name() { return "OBJ export"; }

    @Override
    public String description() {
        return "Writes the displayed surfaces as Wavefront OBJ: the control meshes with their subdivision tags, "
                + "or refined at the viewer's levels, or on the limit surface with normals.";
    }

    @Override public List<String> fileExtensions() { return List.of("obj"); }

    @Override
    public List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) {
        List<PluginOption> out = new ArrayList<>();
        out.add(PluginOption.choice(EXPORT, "Export", "OBJ", CONTROL, List.of(CONTROL, REFINED, LIMIT),
                "The control meshes with their creases, corners, holes and options (one file per surface when there are several), "
                        + "or every surface refined at the viewer's level, or that refinement moved to the limit surface with normals."));
        for (int i = 0; i < surfaces.size(); i++) {
            out.add(PluginOption.of(surfaceKey(i), "Export", surfaces.get(i).name(), PluginOption.Kind.BOOLEAN, "true",
                    "Whether to write this surface."));
        }
        return out;
    }

    private static String surfaceKey(int i) {
        return "surface." + i + ".export";
    }

    @Override
    public PluginResult run(PluginRequest request) throws IOException, InterruptedException {
        List<DisplayedSurface> surfaces = request.surfaces();
        List<PluginOption> options = options(surfaces, request.view());
        Map<String, String> values = request.options();
        String problem = PluginOption.check(options, values);
        if (problem != null) throw new IllegalArgumentException(problem);
        String mode = options.get(0).valueIn(values).strip();
        List<Integer> chosen = new ArrayList<>();
        for (int i = 0; i < surfaces.size(); i++) {
            if (Boolean.parseBoolean(options.get(i + 1).valueIn(values).strip())) chosen.add(i);
        }
        if (chosen.isEmpty()) throw new IllegalArgumentException("no surface is chosen for export (every surface's Export option is false)");
        Path out = request.output();
        Path fileName = out.getFileName();
        if (fileName == null || !fileName.toString().toLowerCase(Locale.ROOT).endsWith(".obj")) {
            throw new IllegalArgumentException("the output file '" + out + "' must end in .obj");
        }
        // Refuse an output that cannot be created before the work that would fill it.
        AtomicFile.checkWritable(out);
        PluginProgress progress = request.progress();
        try {
            checkCancelled(progress);
            return mode.equals(CONTROL) ? writeControl(surfaces, chosen, out, progress)
                    : writeRefined(surfaces, chosen, mode.equals(LIMIT), out, progress);
        } catch (Interrupted e) {
            throw new InterruptedException("the OBJ export was interrupted");
        }
    }

    /** One file per chosen surface (the chosen file itself for one), each a control mesh with its tags. */
    private static PluginResult writeControl(List<DisplayedSurface> surfaces, List<Integer> chosen, Path out, PluginProgress progress)
            throws IOException {
        List<Path> files = chosen.size() == 1 ? List.of(out) : siblings(out, surfaces, chosen);
        List<AtomicFile.Body> bodies = new ArrayList<>();
        long vertices = 0, faces = 0;
        for (int k = 0; k < chosen.size(); k++) {
            DisplayedSurface s = surfaces.get(chosen.get(k));
            String comment = "Spindulys OBJ export: the control mesh of " + s.name() + " (shown as " + s.subdivisionLabel()
                    + ") with its OpenSubdiv tags";
            DoubleConsumer report = reporter(progress, k, chosen.size(), 0, 1, "writing " + s.name());
            bodies.add(o -> ObjWriter.write(s.control(), s.name(), comment, o, report));
            vertices += s.control().vertexCount();
            faces += s.control().faceCount();
        }
        AtomicFile.writeAll(files, bodies);
        progress.progress(1, "done");
        String summary = chosen.size() == 1 ? "control mesh with tags, " + counts(vertices, faces)
                : chosen.size() + " control meshes with tags in " + files.size() + " files, " + counts(vertices, faces);
        return new PluginResult(files, summary);
    }

    /** All chosen surfaces in one file, refined (on the limit surface with {@code limit}) at the host's levels. */
    private static PluginResult writeRefined(List<DisplayedSurface> surfaces, List<Integer> chosen, boolean limit, Path out,
                                             PluginProgress progress) throws IOException {
        for (int i : chosen) {
            DisplayedSurface s = surfaces.get(i);
            try {
                // The heap check render subdivide makes, before anything is refined (one surface is refined at a time).
                SubdivisionSurface.checkLevel(s.level(), s.control().refinedFaceCount(s.level()),
                        limit ? BYTES_PER_FACE + LIMIT_BYTES_PER_FACE : BYTES_PER_FACE);
            } catch (IllegalArgumentException e) {
                throw new IllegalArgumentException("surface " + s.name() + ": " + e.getMessage(), e);
            }
        }
        StringBuilder comment = new StringBuilder("Spindulys OBJ export: ").append(limit ? "limit surfaces with limit normals" : "refined surfaces");
        for (int i : chosen) comment.append('\n').append(surfaces.get(i).name()).append(": ").append(surfaces.get(i).subdivisionLabel());
        long[] counts = new long[2];
        AtomicFile.write(out, o -> {
            ObjWriter.ObjectFile file = new ObjWriter.ObjectFile(o, comment.toString());
            for (int k = 0; k < chosen.size(); k++) {
                DisplayedSurface s = surfaces.get(chosen.get(k));
                RefinedMesh r = refine(s, reporter(progress, k, chosen.size(), 0, 0.5, "refining " + s.name()));
                file.add(s.name(), r, limit, reporter(progress, k, chosen.size(), 0.5, 1, "writing " + s.name()));
                counts[0] += r.vertexCount();
                for (int f = 0; f < r.faceCount(); f++) if (!r.isHole(f)) counts[1]++;
            }
            file.finish();
        });
        progress.progress(1, "done");
        String what = limit ? "limit surface" : "refined";
        String summary = (chosen.size() == 1 ? what : chosen.size() + " surfaces, " + what) + ", " + counts(counts[0], counts[1]);
        return new PluginResult(List.of(out), summary);
    }

    /** Refines level by level, so that a cancel is seen between levels. */
    private static RefinedMesh refine(DisplayedSurface s, DoubleConsumer report) {
        int level = s.scheme() == DisplayedSurface.Scheme.NONE ? 0 : s.level();
        RefinedMesh r = Subdivision.refine(s.control(), 0);
        for (int l = 0; l < level; l++) {
            report.accept((double) l / level);
            r = r.refine();
        }
        report.accept(1);
        return r;
    }

    /**
     * Where a stage's fractions go: surface {@code k} of {@code n} owns the overall span
     * [k/n, (k+1)/n], of which this stage covers [from, to]. Checks for cancel at every report.
     */
    private static DoubleConsumer reporter(PluginProgress progress, int k, int n, double from, double to, String stage) {
        return f -> {
            checkCancelled(progress);
            progress.progress((k + from + (to - from) * f) / n, stage);
        };
    }

    private static void checkCancelled(PluginProgress progress) {
        if (progress.isCancelled()) throw new CancellationException("the OBJ export was cancelled");
        if (Thread.currentThread().isInterrupted()) throw new Interrupted();
    }

    /** Carries an interrupt out of an {@link AtomicFile.Body}, which may throw only IOException. */
    private static final class Interrupted extends RuntimeException {
        Interrupted() { super(null, null, false, false); }
    }

    /**
     * {@code out.obj} and surfaces {@code cube.obj}, {@code torus}: {@code out-cube.obj},
     * {@code out-torus.obj}; characters a file name should not hold become {@code _}, and a name
     * used twice gets {@code -2}, {@code -3}.
     */
    static List<Path> siblings(Path out, List<DisplayedSurface> surfaces, List<Integer> chosen) {
        String name = out.getFileName().toString();
        String stem = name.substring(0, name.length() - ".obj".length());
        Set<String> used = new HashSet<>();
        List<Path> files = new ArrayList<>();
        for (int i : chosen) {
            String base = stem + "-" + FileNames.stem(surfaces.get(i).name(), "surface" + i);
            String candidate = base;
            for (int n = 2; !used.add(candidate.toLowerCase(Locale.ROOT)); n++) candidate = base + "-" + n;
            files.add(out.resolveSibling(candidate + ".obj"));
        }
        return files;
    }

    private static String counts(long vertices, long faces) {
        return vertices + (vertices == 1 ? " vertex, " : " vertices, ") + faces + (faces == 1 ? " face" : " faces");
    }
}
