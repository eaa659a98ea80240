package lt.spindulys.viewer;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Arrays;
import java.util.List;
import java.util.concurrent.CancellationException;
import java.util.concurrent.CountDownLatch;
import java.util.concurrent.TimeUnit;

import javax.imageio.ImageIO;
import javax.swing.SwingUtilities;

import lt.spindulys.files.AtomicFile;
import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;

/**
 * A test plugin with an option of every kind: paints a square of one colour. It reports a coarse
 * red preview, then waits for the test to {@link #release()} it (checking for cancel meanwhile),
 * then reports the full picture in the chosen colour and writes it as PNG. Not registered with
 * ServiceLoader: tests hand it over explicitly.
 */
class FakePlugin implements OutputPlugin {
    static final int COARSE = 0xFFFF0000;

    final CountDownLatch release = new CountDownLatch(1);
    final CountDownLatch waiting = new CountDownLatch(1);
    volatile boolean ranOnEventThread;
    volatile PluginRequest request;
    /** Thrown by the run after the coarse preview when set: how failures reach the user. */
    volatile Exception failure;

    @Override public String id() { return "fake"; }
    @Override public String name() { return "Fake painter"; }
    @Override public String description() { return "Paints a square, for tests."; }
    @Override public List<String> fileExtensions() { return List.of("png"); }

    @Override
    public List<PluginOption> options(List<DisplayedSurface> surfaces, PluginView view) {
        List<PluginOption> o = new ArrayList<>(List.of(
                PluginOption.integer("size", "Size", "Image", Math.min(view.width(), 64), 1, 256, "the square's side in pixels"),
                PluginOption.number("gamma", "Gamma", "Image", 2.2, 0.5, 4, "display gamma"),
                PluginOption.of("color", "Colour", "Image", PluginOption.Kind.COLOR, "0 1 0", "the square's colour"),
                PluginOption.of("border", "Border", "Image", PluginOption.Kind.BOOLEAN, "false", "draw a border"),
                PluginOption.choice("shape", "Shape", "Image", "square", List.of("square", "disc"), "what to paint"),
                PluginOption.of("texture", "Texture", "Image", PluginOption.Kind.FILE, "", "an image to paint"),
                PluginOption.of("title", "Title", "Image", PluginOption.Kind.TEXT, "", "a title")));
        for (int i = 0; i < surfaces.size(); i++) {
            o.add(PluginOption.choice("surface." + i + ".material", "Material", surfaces.get(i).name(), "opaque",
                    List.of("opaque", "mirror"), "how it looks"));
        }
        return o;
    }

    void release() { release.countDown(); }

    @Override
    public PluginResult run(PluginRequest r) throws IOException, InterruptedException {
        request = r;
        ranOnEventThread = SwingUtilities.isEventDispatchThread();
        int size = Integer.parseInt(r.options().getOrDefault("size", "64").strip());
        r.progress().progress(0.1, "coarse preview");
        int[] coarse = new int[4 * 4];
        Arrays.fill(coarse, COARSE);
        r.progress().preview(4, 4, coarse, false);
        waiting.countDown();
        while (!release.await(10, TimeUnit.MILLISECONDS)) {
            if (r.progress().isCancelled()) throw new CancellationException();
        }
        if (r.progress().isCancelled()) throw new CancellationException();
        if (failure != null) {
            if (failure instanceof IOException e) throw e;
            throw (RuntimeException) failure;
        }
        int argb = finalColour(r.options().getOrDefault("color", "0 1 0"));
        int[] pixels = new int[size * size];
        Arrays.fill(pixels, argb);
        r.progress().progress(0.9, "writing");
        BufferedImage image = new BufferedImage(size, size, BufferedImage.TYPE_INT_RGB);
        image.setRGB(0, 0, size, size, pixels, 0, size);
        Path out = r.output();
        AtomicFile.write(out, s -> ImageIO.write(image, "png", s));
        r.progress().preview(size, size, pixels.clone(), true);
        r.progress().progress(1, "done");
        return new PluginResult(List.of(out), size + " x " + size + " square");
    }

    static int finalColour(String colour) {
        String[] p = colour.strip().split("\\s+");
        int red = (int) Math.round(Double.parseDouble(p[0]) * 255);
        int green = (int) Math.round(Double.parseDouble(p[1]) * 255);
        int blue = (int) Math.round(Double.parseDouble(p[2]) * 255);
        return 0xFF000000 | red << 16 | green << 8 | blue;
    }
}
