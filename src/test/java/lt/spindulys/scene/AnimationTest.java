package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNotEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.HashSet;
import java.util.Set;

import org.junit.jupiter.api.Test;

class AnimationTest {
    @Test
    void theClockAndTheShutterAroundEachFrame() {
        Animation a = new Animation(1, 48, 24, 180);
        assertEquals(48, a.frameCount());
        assertEquals(0.5, a.time(12));
        assertEquals(1 / 48.0, a.exposure(), 1e-15);
        assertEquals(0.5 - 1 / 96.0, a.shutterOpen(12), 1e-15);
        assertEquals(0.5 + 1 / 96.0, a.shutterClose(12), 1e-15);
        Animation still = new Animation(0, 0, 30, 0);
        assertEquals(still.shutterOpen(0), still.shutterClose(0));
        // 360 degrees: the shutters of neighbouring frames meet.
        Animation open = new Animation(0, 10, 10, 360);
        assertEquals(open.shutterClose(3), open.shutterOpen(4), 1e-15);
    }

    @Test
    void aFramesSettingsDependOnItsNumberAlone() {
        Animation a = new Animation(1, 100, 24, 90);
        RenderSettings s = RenderSettings.builder().seed(7).samplesPerPixel(9).build();
        assertEquals(a.settingsFor(s, 40), a.settingsFor(s, 40));
        assertEquals(9, a.settingsFor(s, 40).samplesPerPixel());
        Set<Long> seeds = new HashSet<>();
        for (int f = 1; f <= 100; f++) seeds.add(a.settingsFor(s, f).seed());
        assertEquals(100, seeds.size(), "every frame its own noise");
        assertNotEquals(Animation.frameSeed(7, 3), Animation.frameSeed(8, 3));
        assertThrows(IllegalArgumentException.class, () -> a.settingsFor(s, 0));
        assertThrows(IllegalArgumentException.class, () -> a.settingsFor(s, 101));
    }

    @Test
    void refusesValuesOutOfRange() {
        assertThrows(IllegalArgumentException.class, () -> new Animation(-1, 3, 24, 180));
        assertThrows(IllegalArgumentException.class, () -> new Animation(5, 4, 24, 180));
        assertThrows(IllegalArgumentException.class, () -> new Animation(0, Animation.MAX_FRAME + 1, 24, 180));
        assertThrows(IllegalArgumentException.class, () -> new Animation(0, 3, 0, 180));
        assertThrows(IllegalArgumentException.class, () -> new Animation(0, 3, Double.NaN, 180));
        assertThrows(IllegalArgumentException.class, () -> new Animation(0, 3, 24, -1));
        assertThrows(IllegalArgumentException.class, () -> new Animation(0, 3, 24, 361));
    }
}
