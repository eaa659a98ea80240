package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.Map;
import java.util.concurrent.ConcurrentLinkedQueue;
import java.util.concurrent.Executor;
import java.util.concurrent.TimeUnit;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.plugin.DisplayedSurface;
import lt.spindulys.plugin.OutputPlugin;
import lt.spindulys.plugin.PluginOption;
import lt.spindulys.plugin.PluginRequest;
import lt.spindulys.plugin.PluginResult;
import lt.spindulys.plugin.PluginView;

class PluginRunTest {
    @TempDir
    Path dir;

    /** A user-interface thread stand-in: tasks wait until the test runs them, as on a busy event thread. */
    private static final class Queue implements Executor {
        final ConcurrentLinkedQueue<Runnable> tasks = new ConcurrentLinkedQueue<>();
        @Override public void execute(Runnable r) { tasks.add(r); }
        void drain() { for (Runnable r; (r = tasks.poll()) != null; ) r.run(); }
    }

    /** Records what the listener hears, one line per call. */
    private static final class Events implements PluginRun.Listener {
        final List<String> seen = new ArrayList<>();
        @Override public void progress(double f, String stage) { seen.add("progress " + f + " " + stage); }
        @Override public void preview(int w, int h, int[] argb, boolean last) {
            seen.add("preview " + w + "x" + h + (last ? " last" : "") + " " + Integer.toHexString(argb[0]));
        }
        @Override public void finished(PluginResult r) { seen.add("finished " + r.summary()); }
        @Override public void failed(String m, boolean cancelled) { seen.add((cancelled ? "cancelled " : "failed ") + m); }
    }

    private PluginForm.Accepted accepted(Map<String, String> values, String file) {
        return new PluginForm.Accepted(values, dir.resolve(file));
    }

    @Test
    void aRunReportsPreviewsThenItsEndAndWritesTheFile() throws Exception {
        FakePlugin plugin = new FakePlugin();
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(plugin, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of("size", "3", "color", "0 0 1"), "out.png"), ui, events);
        assertTrue(plugin.waiting.await(10, TimeUnit.SECONDS));
        ui.drain();
        assertEquals(List.of("progress 0.1 coarse preview", "preview 4x4 ffff0000"), events.seen);
        plugin.release();
        assertTrue(run.await(10, TimeUnit.SECONDS));
        ui.drain();
        assertEquals(List.of("progress 0.1 coarse preview", "preview 4x4 ffff0000", "progress 1.0 done", "preview 3x3 last ff0000ff",
                "finished 3 x 3 square"), events.seen);
        assertTrue(Files.isRegularFile(dir.resolve("out.png")));
        assertFalse(plugin.ranOnEventThread);
        assertEquals(Fixtures.surfaces().size(), plugin.request.surfaces().size());
    }

    @Test
    void aFloodOfProgressReachesTheUserInterfaceAsItsNewestValue() throws Exception {
        OutputPlugin chatty = new Stub() {
            @Override public PluginResult run(PluginRequest r) {
                for (int i = 1; i <= 10_000; i++) r.progress().progress(i / 10_000.0, "step");
                for (int i = 1; i <= 100; i++) r.progress().preview(1, 1, new int[] {i}, i == 100);
                return new PluginResult(List.of(), "done");
            }
        };
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(chatty, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of(), "x.png"), ui, events);
        assertTrue(run.await(10, TimeUnit.SECONDS));
        assertTrue(ui.tasks.size() <= 3, "one pending update of each kind and the end, found " + ui.tasks.size() + " tasks");
        ui.drain();
        assertEquals(List.of("progress 1.0 step", "preview 1x1 last 64", "finished done"), events.seen);
    }

    @Test
    void aCancelledRunSaysSoAndWritesNothing() throws Exception {
        FakePlugin plugin = new FakePlugin();
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(plugin, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of(), "out.png"), ui, events);
        assertTrue(plugin.waiting.await(10, TimeUnit.SECONDS));
        assertFalse(run.isCancelled());
        run.cancel();
        assertTrue(run.isCancelled());
        assertTrue(run.await(10, TimeUnit.SECONDS));
        assertTrue(run.isDone());
        ui.drain();
        assertEquals("cancelled cancelled; nothing written", events.seen.get(events.seen.size() - 1));
        assertFalse(Files.exists(dir.resolve("out.png")));
    }

    @Test
    void failuresBecomeTheCommandLinesOneLine() throws Exception {
        assertEquals("failed render: cannot write 'x': disk full", end(new IOException("cannot write 'x': disk full")));
        assertEquals("failed surface cube: face 3 has 2 corners", end(new IllegalArgumentException("surface cube: face 3 has 2 corners")));
        assertEquals("failed render: internal error: java.lang.IllegalStateException: broken", end(new IllegalStateException("broken")));
        assertEquals("failed render: /x/y.png", end(new NoSuchFileException("/x/y.png")));
        OutputPlugin broken = new Stub() {
            @Override public PluginResult run(PluginRequest r) { throw new NoClassDefFoundError("com/example/Missing"); }
        };
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(broken, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of(), "x.png"), ui, events);
        assertTrue(run.await(10, TimeUnit.SECONDS));
        ui.drain();
        assertEquals(List.of("failed render: internal error: java.lang.NoClassDefFoundError: com/example/Missing"), events.seen,
                "an error of a plugin's own ends its run with a message, not silently");
    }

    @Test
    void aPreviewOfTheWrongSizeFailsTheRunWithWhatWasWrong() throws Exception {
        OutputPlugin wrong = new Stub() {
            @Override public PluginResult run(PluginRequest r) {
                r.progress().preview(4, 3, new int[10], false);
                return new PluginResult(List.of(), "no");
            }
        };
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(wrong, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of(), "x.png"), ui, events);
        assertTrue(run.await(10, TimeUnit.SECONDS));
        ui.drain();
        assertEquals(List.of("failed a preview of 4 x 3 pixels needs 12 values, found 10"), events.seen);
    }

    private String end(Exception thrown) throws Exception {
        FakePlugin plugin = new FakePlugin();
        plugin.failure = thrown;
        plugin.release();
        Queue ui = new Queue();
        Events events = new Events();
        PluginRun run = PluginRun.start(plugin, Fixtures.surfaces(), Fixtures.view(8, 8), accepted(Map.of(), "out.png"), ui, events);
        assertTrue(run.await(10, TimeUnit.SECONDS));
        ui.drain();
        assertFalse(Files.exists(dir.resolve("out.png")));
        return events.seen.get(events.seen.size() - 1);
    }

    /** A plugin with no options, for runs that do one thing. */
    private abstract static class Stub implements OutputPlugin {
        @Override public String id() { return "stub"; }
        @Override public String name() { return "Stub"; }
        @Override public String description() { return "Does one thing."; }
        @Override public List<String> fileExtensions() { return List.of("png"); }
        @Override public List<PluginOption> options(List<DisplayedSurface> s, PluginView v) { return List.of(); }
    }
}
