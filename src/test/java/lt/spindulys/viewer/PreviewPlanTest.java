package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.*;

import java.util.EnumSet;
import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.image.Aov;
import lt.spindulys.scene.RenderSettings;

/** The passes of the scene preview: coarse to full, none repeated, the last one the scene's own settings. */
class PreviewPlanTest {
    private static String describe(List<PreviewPlan.Pass> passes) {
        StringBuilder s = new StringBuilder();
        for (PreviewPlan.Pass p : passes) s.append(p.describe()).append(p.coarse() ? " coarse" : "").append(p.last() ? " last" : "").append("; ");
        return s.toString();
    }

    @Test
    void anEighthAQuarterAHalfThenFullAtOneSampleThenTheScenesSamples() {
        RenderSettings s = RenderSettings.builder().size(640, 450).samplesPerPixel(16).build();
        assertEquals("80x57, 1 sample coarse; 160x113, 1 sample coarse; 320x225, 1 sample; 640x450, 1 sample; 640x450, 16 samples last; ",
                describe(PreviewPlan.of(s)));
    }

    @Test
    void passesThatWouldRepeatAreLeftOut() {
        assertEquals("1x1, 1 sample coarse; 2x2, 1 sample; 4x4, 1 sample last; ",
                describe(PreviewPlan.of(RenderSettings.builder().size(4, 4).build())));
        assertEquals("1x1, 1 sample; 1x1, 3 samples last; ", describe(PreviewPlan.of(RenderSettings.builder().size(1, 1).samplesPerPixel(3).build())));
    }

    @Test
    void coarsePassesRenderOneSampleInOneTimeStepWithoutRenderPasses() {
        RenderSettings s = RenderSettings.builder().size(64, 32).samplesPerPixel(8).timeSteps(4).aovs(EnumSet.of(Aov.DEPTH)).build();
        List<PreviewPlan.Pass> plan = PreviewPlan.of(s);
        RenderSettings first = plan.get(0).apply(s);
        assertEquals(8, first.width());
        assertEquals(4, first.height());
        assertEquals(1, first.samplesPerPixel());
        assertEquals(1, first.timeSteps());
        assertTrue(first.aovs().isEmpty());
        RenderSettings last = plan.get(plan.size() - 1).apply(s);
        assertEquals(s.toBuilder().aovs(EnumSet.noneOf(Aov.class)).build(), last, "the last pass is the scene's settings, without passes");
    }

    @Test
    void coarsePassesOfAnAdaptivelySampledDenoisedSceneSampleUniformlyAndAreNotDenoised() {
        // A minimum of 64 samples would refuse a one-sample pass: the coarse passes sample uniformly.
        RenderSettings s = RenderSettings.builder().size(64, 32).samplesPerPixel(256).noiseThreshold(0.01).minSamples(64)
                .denoise(true).build();
        List<PreviewPlan.Pass> plan = PreviewPlan.of(s);
        for (PreviewPlan.Pass p : plan.subList(0, plan.size() - 1)) {
            RenderSettings coarse = p.apply(s);
            assertFalse(coarse.adaptiveSampling(), p.describe());
            assertFalse(coarse.denoise(), p.describe());
            assertSame(coarse, coarse.checkNoiseControl(), p.describe());
        }
        RenderSettings last = plan.get(plan.size() - 1).apply(s);
        assertTrue(last.adaptiveSampling());
        assertEquals(64, last.minSamples());
        assertTrue(last.denoise());
    }
}
