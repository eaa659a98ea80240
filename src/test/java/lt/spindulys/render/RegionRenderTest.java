package lt.spindulys.render;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;
import java.util.concurrent.atomic.AtomicLong;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.image.FrameBuffer;
import lt.spindulys.image.PixelRegion;
import lt.spindulys.io.SceneParser;
import lt.spindulys.scene.SceneBuilder;

/**
 * A region of a frame ({@link RenderJob#region}, {@link RenderJob#tile}) holds exactly the linear
 * values a whole render has there, for every way samples are drawn: pixel, lens, time and light
 * samples in one pass, the thesis's time steps, pixel filters wider than a pixel, and a surface
 * refined lazily while it is traced, and adaptive sampling.
 */
class RegionRenderTest {
    @TempDir Path dir;

    private static final String SCENE = """
            settings { width 29 height 19 samples 4 }
            camera { eye 0 1.5 -5 lookat 0 0.5 0 aperture 0.05 }
            rectlight { center 2 4 -3  normal 0 -1 0  tangent 1 0 0  width 1  height 1  intensity 4  samples 2 }
            plane { normal 0 1 0  material { kr 0.2 } }
            sphere { center -1 0.5 0 radius 0.5 material { color 1 0 0 } motion { direction 1 0 0 speed 0.3 } }
            subdiv { file "models/cube.dat"  method lazy  material { color 0.2 0.4 0.9 }  translate 1 0.5 0  scale 0.5 }
            """;

    private SceneBuilder scene(String extra) throws IOException {
        Path models = Path.of("scenes/models/cube.dat").toAbsolutePath();
        Files.createDirectories(dir.resolve("models"));
        Files.copy(models, dir.resolve("models/cube.dat"), java.nio.file.StandardCopyOption.REPLACE_EXISTING);
        Path p = dir.resolve("scene.dat");
        Files.writeString(p, SCENE.replace("samples 4 }", (extra.startsWith("samples") ? "" : "samples 4 ") + extra + " }"));
        return SceneParser.parse(p);
    }

    /** Asserts that {@code part} holds exactly the pixels of region r of {@code whole}. */
    static void assertRegionOfWhole(FrameBuffer whole, PixelRegion r, FrameBuffer part) {
        assertEquals(r.width() + "x" + r.height(), part.width() + "x" + part.height());
        for (int y = r.y0(); y < r.y1(); y++) {
            for (int x = r.x0(); x < r.x1(); x++) {
                for (int c = 0; c < 3; c++) {
                    assertEquals(whole.get(x, y, c), part.get(x - r.x0(), y - r.y0(), c), 0.0, "pixel " + x + "," + y + " of region " + r);
                }
            }
        }
    }

    @Test
    void regionsAndTilesHoldTheWholeFramesValues() throws Exception {
        // Filters wider than a pixel draw samples beyond it, but each still adds to its own pixel only: no apron is needed.
        // Adaptive sampling stops each pixel on its own samples only: its rounds are as a whole render's.
        for (String extra : new String[] {"", "timesteps 2", "filter blackman-harris", "filter mitchell", "filter gaussian filterwidth 2 timesteps 2",
                "samples 24 noisethreshold 0.05 minsamples 8", "samples 24 noisethreshold 0.05 minsamples 8 filter mitchell"}) {
            SceneBuilder b = scene(extra);
            FrameBuffer whole = RenderJob.of(b).threads(2).run().frame();
            List<PixelRegion> regions = new ArrayList<>(List.of(new PixelRegion(0, 29, 0, 19), new PixelRegion(3, 20, 5, 6),
                    new PixelRegion(28, 29, 18, 19), new PixelRegion(0, 17, 2, 19)));
            for (PixelRegion r : regions) {
                RenderResult part = RenderJob.of(b).region(r).threads(3).run();
                assertEquals(r, part.region().orElseThrow());
                assertRegionOfWhole(whole, r, part.frame());
            }
            for (int i = 1; i <= 4; i++) {
                RenderResult part = RenderJob.of(b).tile(i, 4).threads(1).run();
                assertRegionOfWhole(whole, PixelRegion.band(i, 4, 29, 19), part.frame());
            }
        }
    }

    @Test
    void progressCountsTheRegionsPixelsAndTilesAreInItsCoordinates() throws Exception {
        SceneBuilder b = scene("");
        AtomicLong total = new AtomicLong(), last = new AtomicLong();
        List<int[]> tiles = new ArrayList<>();
        RenderJob.of(b).region(new PixelRegion(1, 21, 2, 5)).threads(1)
                .progress((done, all) -> { last.set(done); total.set(all); })
                .tiles((fb, x0, y0, x1, y1) -> tiles.add(new int[] {x0, y0, x1, y1}))
                .run();
        assertEquals(60, total.get());
        assertEquals(60, last.get());
        long covered = 0;
        for (int[] t : tiles) {
            assertTrue(t[0] >= 0 && t[1] >= 0 && t[2] <= 20 && t[3] <= 3, java.util.Arrays.toString(t));
            covered += (long) (t[2] - t[0]) * (t[3] - t[1]);
        }
        assertEquals(60, covered);
    }

    @Test
    void aRegionOutsideTheFrameOrWithPassesIsRefusedBeforeRendering() throws Exception {
        SceneBuilder b = scene("");
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, () -> RenderJob.of(b).region(new PixelRegion(0, 30, 0, 1)).run());
        assertEquals("the region 0,30,0,1 reaches past the 29x19 frame (x1 is at most 29)", e.getMessage());
        e = assertThrows(IllegalArgumentException.class, () -> RenderJob.of(b).tile(1, 20).run());
        assertEquals("the 29x19 frame has 19 rows, too few for 20 tiles of whole rows", e.getMessage());
        RenderJob passes = RenderJob.of(b).region(new PixelRegion(0, 2, 0, 2))
                .settings(s -> s.toBuilder().aovs(java.util.EnumSet.of(lt.spindulys.image.Aov.DEPTH)).build());
        assertThrows(IllegalArgumentException.class, passes::run);
        assertEquals(RenderJob.Stage.SETTINGS, passes.stage());
        Path jpg = dir.resolve("tile.jpg");
        assertThrows(IllegalArgumentException.class, () -> RenderJob.of(b).tile(1, 2).output(jpg).run());
        assertFalse(Files.exists(jpg));
    }
}
