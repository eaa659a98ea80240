package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertInstanceOf;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;

import lt.spindulys.camera.AnimatedCamera;
import lt.spindulys.camera.PinholeCamera;
import lt.spindulys.camera.ThinLensCamera;
import lt.spindulys.math.Keyframes;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Animation;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.RenderSettings;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;

/** The animation statement, keys and turntables reach the builder API with the values written; bad ones are located errors. */
class SceneParserAnimationTest {
    private static SceneBuilder parse(String text) { return SceneParser.parse(text, "a.dat", null); }

    private static String error(String text) {
        return assertThrows(SceneException.class, () -> parse(text)).getMessage();
    }

    private static final String ANIM = "animation { frames 1 48  fps 24  shutter 90 }\n";

    @Test
    void animationStatement() {
        Animation a = parse(ANIM).animation();
        assertEquals(new Animation(1, 48, 24, 90), a);
        assertEquals(new Animation(0, 9, 24, 180), parse("animation { frames 0 9 }").animation());
        assertNull(parse("sphere { }").animation());
    }

    @Test
    void keysAreTimedByFrameOverFps() {
        SceneBuilder b = parse(ANIM + "sphere { keys { interpolation smooth  pivot 1 0 0  key 12 { translate 1 2 3 }  key 36 { rotate 0 90 0  scale 2 }  key 40.5 { } } }");
        Keyframes k = b.objects().get(0).keys();
        assertEquals(3, k.size());
        assertEquals(12 / 24.0, k.time(0));
        assertEquals(36 / 24.0, k.time(1));
        assertEquals(40.5 / 24.0, k.time(2));
        assertEquals(Keyframes.Interpolation.SMOOTH, k.interpolation());
        assertEquals(1, k.value(0, 0.5), 1e-12); // frame 12
        assertEquals(1, k.value(0, 0), 1e-12);   // held before the first key
        assertEquals(90, k.value(4, 1.5), 1e-12);
        assertEquals(2, k.value(7, 1.5), 1e-12);
        assertEquals(1, k.value(6, 40.5 / 24), 1e-12); // an empty pose is the identity's
        assertEquals(new Vec3(1, 0, 0), k.basis().point(Vec3.ZERO));
    }

    @Test
    void csgNodesOperandsAndTheCameraTakeKeysAndTurntables() {
        SceneBuilder b = parse(ANIM + "camera { eye 0 1 -5  lookat 0 0 0  aperture 0.1  turntable { axis 0 0 1  turns 2 } }\n"
                + "difference { box { min -1 -1 -1 max 1 1 1 }  sphere { radius 0.5 keys { key 1 { } key 2 { translate 1 0 0 } } }  turntable { } }");
        AnimatedCamera c = assertInstanceOf(AnimatedCamera.class, b.camera());
        assertInstanceOf(ThinLensCamera.class, c.base());
        // Two turns about z from frame 1 to frame 49: a quarter of a turn after 6 frames.
        Vec3 p = c.keys().at(7 / 24.0).point(new Vec3(1, 0, 0));
        assertEquals(0, p.x(), 1e-9);
        assertEquals(1, p.y(), 1e-9);
        Bool d = (Bool) b.objects().get(0);
        assertTrue(d.keys() != null && d.operands().get(1).keys() != null);
        Scene s = b.forFrame(24).build();
        for (GObject o : ((Bool) s.objects().get(0)).operands()) assertTrue(o.isMoving(), "operands move with the node");
        // The operand's bounds hold it where its keys put it: x from 0 (frame 1) to 1 (frame 2 on).
        assertTrue(s.objects().get(0).bounds().maxX() >= 1);
    }

    /** Where its keys hold one pose through a frame's shutter, an object is placed as a still one. */
    @Test
    void anObjectIsStillInFramesWhereItsKeysHold() {
        SceneBuilder b = parse(ANIM + "sphere { keys { key 10 { } key 20 { translate 1 0 0 } } }");
        assertTrue(!b.forFrame(5).build().objects().get(0).isMoving());
        assertTrue(b.forFrame(15).build().objects().get(0).isMoving());
        GObject after = b.forFrame(30).build().objects().get(0);
        assertTrue(!after.isMoving());
        assertEquals(new Vec3(1, 0, 0), after.objectToWorld(0).point(Vec3.ZERO));
    }

    @Test
    void aFramesSettingsAreTheSceneSettingsWithItsShutterAndSeed() {
        SceneBuilder b = parse("settings { seed 5 samples 4 }\n" + ANIM + "sphere { }");
        RenderSettings f = b.forFrame(12).settings();
        assertEquals(0.5 - 1 / 192.0, f.shutterOpen(), 1e-15);
        assertEquals(0.5 + 1 / 192.0, f.shutterClose(), 1e-15);
        assertEquals(Animation.frameSeed(5, 12), f.seed());
        assertEquals(4, f.samplesPerPixel());
        assertEquals(5, b.settings().seed(), "the builder itself is unchanged");
        assertThrows(IllegalArgumentException.class, () -> b.forFrame(49));
        assertThrows(IllegalArgumentException.class, () -> parse("sphere { }").forFrame(1));
    }

    @Test
    void badAnimationsAreLocatedErrors() {
        assertEquals("a.dat:1:12: 'keys' needs an animation statement before it (such as animation { frames 1 48  fps 24 }): key frames are read on its clock",
                error("sphere {   keys { key 1 { } } }"));
        assertTrue(error("camera { eye 0 0 -1 lookat 0 0 0 turntable { } }").startsWith("a.dat:1:34: 'turntable' needs an animation statement"));
        assertEquals("a.dat:2:42: key frame 12 is not after the previous key's frame 12 (at 2:31): keys must be in increasing frame order, each frame once",
                error(ANIM + "sphere { keys { key 1 { } key 12 { } key 12 { } } }"));
        assertTrue(error(ANIM + "sphere { keys { key 5 { } key 3 { } } }").startsWith("a.dat:2:31: key frame 3 is not after the previous key's frame 5"));
        assertEquals("a.dat:2:10: keys needs at least one 'key FRAME { translate ... rotate ... scale ... }'", error(ANIM + "sphere { keys { interpolation ease } }"));
        assertTrue(error(ANIM + "sphere { keys { key 1 { } } turntable { } }").startsWith("a.dat:2:29: 'turntable' and 'keys' (at 2:10) exclude each other"));
        assertTrue(error(ANIM + "camera { eye 0 0 -1 lookat 0 0 0 keys { key 1 { scale 2 } } }").startsWith("a.dat:2:34: a camera's keys may translate and rotate it but not scale it"));
        assertTrue(error(ANIM + "sphere { keys { key 1 { scale 0 } } }").startsWith("a.dat:2:25: key scale must be positive"));
        assertTrue(error(ANIM + "sphere { keys { key 1 { spin 3 } } }").startsWith("a.dat:2:25: unknown property 'spin' in key"));
        assertTrue(error(ANIM + "sphere { keys { key 1 { rotate y 90 } } }").startsWith("a.dat:2:32: expected 3 numbers for 'rotate'"));
        assertTrue(error(ANIM + "sphere { keys { interpolation cubic key 1 { } } }").startsWith("a.dat:2:31: "));
        assertTrue(error(ANIM + "sphere { keys { key { } } }").startsWith("a.dat:2:21: expected a frame number after 'key'"));
        assertTrue(error(ANIM + "sphere { turntable { axis 0 0 0 } }").startsWith("a.dat:2:22: turntable axis must be non-zero"));
        assertEquals("a.dat:1:1: animation needs 'frames'", error("animation { fps 24 }"));
        assertTrue(error("animation { frames 5 2 }").startsWith("a.dat:1:13: last frame must be between the first (5)"));
        assertTrue(error("animation { frames 1 2 fps 0 }").startsWith("a.dat:1:24: fps must be between 0.001 and 1000"));
        assertTrue(error("animation { frames 1 2 shutter 400 }").startsWith("a.dat:1:24: shutter angle must be between 0 and 360"));
        assertTrue(error("animation { frames 1 2.5 }").startsWith("a.dat:1:22: expected an integer for 'frames'"));
        assertTrue(error(ANIM + "animation { frames 1 2 }").startsWith("a.dat:2:1: animation is already defined at 1:1"));
        String shutter = "a.dat:1:12: 'shutter' in settings does not combine with the animation at ";
        assertTrue(error("settings { shutter 0 1 }\n" + ANIM).startsWith(shutter + "2:1"));
        assertTrue(error(ANIM + "settings { shutter 0 1 }").startsWith(shutter.replace("1:12", "2:12") + "1:1"));
    }

    @Test
    void aMotionMustFitEveryFramesShutter() {
        // The motion finishes at 0.1, before frame 48's shutter opens (48 / 24 = 2).
        assertTrue(error(ANIM + "sphere { motion { translate 1 0 0  finish 0.1 } }").startsWith("a.dat:2:"));
        parse(ANIM + "sphere { motion { translate 1 0 0 } }"); // open times: each frame's own shutter
    }

    @Test
    void aStillStaysAStill() {
        SceneBuilder b = parse("camera { eye 0 0 -1 lookat 0 0 0 }  sphere { }");
        assertInstanceOf(PinholeCamera.class, b.camera());
        assertNull(b.objects().get(0).keys());
    }
}
