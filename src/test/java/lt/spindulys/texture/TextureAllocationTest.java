package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertTrue;
import static org.junit.jupiter.api.Assumptions.assumeTrue;

import java.lang.management.ManagementFactory;
import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** Textures are evaluated per shading point: evaluate must not allocate. */
class TextureAllocationTest {
    @Test
    void evaluateDoesNotAllocate() {
        assumeTrue(ManagementFactory.getThreadMXBean() instanceof com.sun.management.ThreadMXBean,
                "needs HotSpot's per-thread allocation counter");
        com.sun.management.ThreadMXBean mx = (com.sun.management.ThreadMXBean) ManagementFactory.getThreadMXBean();
        assumeTrue(mx.isThreadAllocatedMemorySupported() && mx.isThreadAllocatedMemoryEnabled());

        List<Texture> textures = new ArrayList<>(ProceduralTest.all());
        for (Filter f : Filter.values()) {
            for (Wrap w : Wrap.values()) textures.add(new ImageTexture(ImageTextureTest.blockChecker(), f, w));
        }
        TexturePoint p = new TexturePoint();
        double[] rgb = new double[3];
        long tid = Thread.currentThread().getId();
        double sink = 0;
        run(textures, p, rgb, 200);  // warm up (class loading, first calls)
        long before = mx.getThreadAllocatedBytes(tid);
        sink += run(textures, p, rgb, 5000);
        long used = mx.getThreadAllocatedBytes(tid) - before;
        // 5000 x 17 evaluations: even one small object per call would be megabytes.
        assertTrue(used < 64 * 1024, "allocated " + used + " bytes (sink " + sink + ")");
    }

    private static double run(List<Texture> textures, TexturePoint p, double[] rgb, int n) {
        double s = 0;
        for (int i = 0; i < n; i++) {
            p.u = i * 0.0137 - 3;
            p.v = i * 0.0071 + 0.2;
            p.x = p.u * 0.7;
            p.y = p.v * 1.3;
            p.z = i * 0.001;
            p.footprint = (i % 7) * 0.05;
            for (int k = 0; k < textures.size(); k++) {
                textures.get(k).evaluate(p, rgb);
                s += rgb[0];
            }
        }
        return s;
    }
}
