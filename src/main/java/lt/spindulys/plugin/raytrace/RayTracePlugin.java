package lt.spindulys.plugin.raytrace;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.EnumSet;
import java.util.List;
import java.util.Locale;
import java.util.concurrent.CancellationException;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.files.FileNames;
import lt.spindulys.image.Aov;
import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.ImageOptions;
import lt.spindulys.image.ImageWriter;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginProgress;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;
import lt.spindulys.render.RenderJob;
import lt.spindulys.render.RenderResult;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.texture.TextureCache;

/**
 * The ray-tracing output plugin of the thesis's chapter 7: it makes a scene of the surfaces a
 * viewer shows, through the public {@link SceneBuilder} API, renders it with a
 * {@link RenderJob} and writes a .jpg (the thesis's format), .png or .tga. Each surface gets a
 * material (opaque, transparent glass or mirror), optionally an image texture with a mapping,
 * and is rendered as its limit surface, at the host's level or adaptively; a lighting preset,
 * an optional floor and the background complete the picture. It can also write the scene it
 * built as a .dat file with each control mesh as an OBJ beside it, and a picture that
 * identifies each surface by colour with a legend. The options are listed in docs/plugins.md.
 *
 * <p>A run renders a quarter-size preview with one sample first and hands it to
 * {@link PluginProgress#preview}, then the full picture, previewed as its tiles finish (over the
 * coarse preview, at most four times a second); all files are written together and atomically
 * at the end, so a cancelled or failed run writes nothing.
 */
public final class RayTracePlugin implements OutputPlugin {
    /** The plugin's identifier. */
    public static final String ID = "raytrace";

    /** The files a run writes beside its main output: the identification picture's suffix. */
    public static final String IDENTIFICATION_SUFFIX = ".surfaces.png";

    /** Least time between two previews of the picture as its tiles finish. */
    static final long PREVIEW_INTERVAL_NANOS = 250_000_000L;

    private final long previewIntervalNanos;

    /** A plugin; it keeps no state between runs. */
    public RayTracePlugin() {
        this(PREVIEW_INTERVAL_NANOS);
    }

    /** A plugin that previews the picture as often as this (tests: 0, at every tile). */
    RayTracePlugin(long previewIntervalNanos) {
        this.previewIntervalNanos = previewIntervalNanos;
    }

    @Override public String id() { return ID; }

    @Override public String name() { return "Ray tracer"; }

    @Override public String description() {
        return "Ray-traces the displayed surfaces with glass, mirror or textured materials into a picture.";
    }

    @Override public List<String> fileExtensions() { return List.of("jpg", "png", "tga"); }

    @Override
    public List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) {
        if (surfaces.isEmpty()) throw new IllegalArgumentException("there is no surface to output");
        return RayTraceOptions.options(surfaces, view);
    }

    @Override
    public PluginResult run(PluginRequest request) throws IOException, InterruptedException {
        long start = System.nanoTime();
        Path out = request.output();
        String ext = FileNames.extension(out);
        if (!fileExtensions().contains(ext)) {
            throw new IllegalArgumentException("the ray tracer writes .jpg, .png or .tga files, not '" + SceneDescription.oneLine(out.toString()) + "'");
        }
        RayTraceOptions.Resolved resolved = RayTraceOptions.resolve(request.surfaces(), request.view(), request.options());
        SceneDescription scene = resolved.scene();
        PluginProgress progress = request.progress();

        // Every file is checked before any work, so an unwritable place fails at once.
        List<Path> files = new ArrayList<>();
        files.add(out);
        Path identification = resolved.identify() ? beside(out, IDENTIFICATION_SUFFIX) : null;
        if (identification != null) files.add(identification);
        SavedScene saved = resolved.saveScene() ? SavedScene.beside(out, scene) : null;
        if (saved != null) files.addAll(saved.files());
        ImageWriter.checkOutput(out);
        for (Path f : files.subList(1, files.size())) AtomicFile.checkWritable(f);

        int w = scene.image().width(), h = scene.image().height();
        try {
            // Checked here too (RenderJob checks it again) so that the message names the options.
            FrameBuffer.checkHeap(w, h, identification != null ? EnumSet.of(Aov.OBJECT) : EnumSet.noneOf(Aov.class));
        } catch (IllegalArgumentException e) {
            throw new IllegalArgumentException("Image width (width) and height (height): " + e.getMessage(), e);
        }
        TextureCache textures = new TextureCache();
        // A coarse preview first: a quarter of the size, one sample, from a scene of its own so
        // that nothing refined for it is shared with the full render.
        checkCancelled(progress);
        int pw = Math.max(1, w / 4), ph = Math.max(1, h / 4);
        RenderJob previewJob = RenderJob.of(scene.toBuilder(textures)).settings(s -> s.toBuilder().size(pw, ph).samplesPerPixel(1).build());
        RenderResult preview = render(previewJob, progress, "rendering the preview");
        int[] coarse = argb(preview.image());
        progress.preview(pw, ph, coarse, false);

        checkCancelled(progress);
        RenderJob job = RenderJob.of(scene.toBuilder(textures))
                .tiles(new TilePreview(w, h, coarse, pw, ph, progress, previewIntervalNanos));
        // The object pass is one more ray per pixel and leaves the picture as it is.
        if (identification != null) job.settings(s -> s.toBuilder().aovs(EnumSet.of(Aov.OBJECT)).build());
        RenderResult result = render(job, progress, "rendering");
        checkCancelled(progress);

        progress.progress(0, "writing");
        List<AtomicFile.Body> bodies = new ArrayList<>();
        bodies.add(ImageWriter.encoder(result.frame(), out, new ImageOptions(true, ImageOptions.DEFAULT.jpegQuality()))::accept);
        if (identification != null) {
            List<String> rendered = scene.surfaces().stream().map(SceneDescription.SurfaceSpec::renderedAs).toList();
            IdentificationImage id = IdentificationImage.of(result.passes().orElseThrow(), request.surfaces(), rendered);
            bodies.add(ImageWriter.pngEncoder(id.width(), id.height(), id.rgb())::accept);
        }
        if (saved != null) bodies.addAll(saved.bodies(request.surfaces()));
        // Encoding a large picture takes a while: a cancel during it still wins, as every file is
        // checked before and after it is written, and writeAll deletes its temporary files when
        // a body throws, before anything is renamed.
        List<AtomicFile.Body> cancellable = new ArrayList<>(bodies.size());
        for (AtomicFile.Body b : bodies) {
            cancellable.add(os -> {
                checkCancelled(progress);
                b.write(os);
                checkCancelled(progress);
            });
        }
        AtomicFile.writeAll(files, cancellable);
        progress.progress(1, "writing");
        progress.preview(w, h, argb(result.image()), true);
        double seconds = (System.nanoTime() - start) / 1e9;
        String summary = String.format(Locale.ROOT, "%d x %d, %d sample%s, %.1f s", w, h, scene.image().samples(),
                scene.image().samples() == 1 ? "" : "s", seconds);
        return new PluginResult(files, summary);
    }

    /**
     * Runs a job, forwarding its progress and cancelling it once the host says so: from the
     * job's progress reports, and from a watcher thread for the steps that report nothing
     * (building the scene's subdivision).
     */
    private static RenderResult render(RenderJob job, PluginProgress progress, String stage) throws IOException, InterruptedException {
        long[] shown = {-1};
        job.progress((done, total) -> {
            if (progress.isCancelled()) job.cancel();
            synchronized (shown) {
                // Reports from several render threads may come out of order; the host sees them rise.
                if (done > shown[0]) {
                    shown[0] = done;
                    progress.progress(total > 0 ? (double) done / total : 1, stage);
                }
            }
        });
        Thread watcher = new Thread(() -> {
            try {
                while (!progress.isCancelled()) Thread.sleep(20);
                job.cancel();
            } catch (InterruptedException e) {
                // the render ended
            }
        }, "raytrace-cancel-watcher");
        watcher.setDaemon(true);
        watcher.start();
        progress.progress(0, stage);
        try {
            return job.run();
        } finally {
            watcher.interrupt();
            watcher.join();
        }
    }

    private static void checkCancelled(PluginProgress progress) {
        if (progress.isCancelled()) throw new CancellationException("the render was cancelled");
    }

    /** Pixels of a TYPE_INT_RGB image as opaque 0xAARRGGBB, rows from the top. */
    private static int[] argb(BufferedImage img) {
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }

    /** The file beside {@code out} with its extension replaced by {@code suffix}: out.jpg and ".dat" give out.dat. */
    static Path beside(Path out, String suffix) {
        String name = out.getFileName().toString();
        int dot = name.lastIndexOf('.');
        return out.resolveSibling((dot < 0 ? name : name.substring(0, dot)) + suffix);
    }

    /** The scene's text and its control meshes, to be written beside the picture. */
    private record SavedScene(Path dat, List<Path> meshes, SceneDescription scene) {
        static SavedScene beside(Path out, SceneDescription scene) {
            Path dat = RayTracePlugin.beside(out, ".dat");
            List<Path> meshes = new ArrayList<>();
            for (SceneDescription.SurfaceSpec s : scene.surfaces()) meshes.add(RayTracePlugin.beside(out, "." + s.index() + "-" + FileNames.stem(s.name(), "surface") + ".obj"));
            return new SavedScene(dat, meshes, scene);
        }

        List<Path> files() {
            List<Path> all = new ArrayList<>();
            all.add(dat);
            all.addAll(meshes);
            return all;
        }

        List<AtomicFile.Body> bodies(List<DisplayedSurface> surfaces) {
            List<String> names = meshes.stream().map(m -> m.getFileName().toString()).toList();
            Path dir = dat.toAbsolutePath().getParent();
            String text = scene.toText(names, dir, "Written by the Spindulys ray-tracing plugin; render it with: render " + dat.getFileName());
            List<AtomicFile.Body> bodies = new ArrayList<>();
            bodies.add(os -> os.write(text.getBytes(StandardCharsets.UTF_8)));
            for (int i = 0; i < meshes.size(); i++) {
                DisplayedSurface s = surfaces.get(i);
                String comment = "control mesh of '" + SceneDescription.oneLine(s.name()) + "' (" + s.subdivisionLabel() + " in the viewer)";
                bodies.add(os -> lt.spindulys.io.ObjWriter.write(s.control(), SceneDescription.oneLine(s.name()), comment, os));
            }
            return bodies;
        }
    }
}
