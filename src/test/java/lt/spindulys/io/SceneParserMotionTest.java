package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Motion;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;

/** Motion blocks, shutter and timesteps reach the builder API with the values written. */
class SceneParserMotionTest {
    private static SceneBuilder parse(String text) { return SceneParser.parse(text, "m.dat", null); }

    @Test
    void generalMotionKeys() {
        SceneBuilder b = parse("box { min 0 0 0 max 1 1 1 motion { translate 1 2 3  rotate 0 0 2 90  scale 2 1 0.5  pivot 0.5 0.5 0.5  start 0.25  finish 0.75 } }");
        Motion m = b.objects().get(0).motion();
        assertEquals(new Vec3(1, 2, 3), m.translation());
        assertEquals(new Vec3(0, 0, 1), m.axis());
        assertEquals(90, m.degrees(), 1e-12);
        assertEquals(new Vec3(2, 1, 0.5), m.scale());
        assertEquals(new Vec3(0.5, 0.5, 0.5), m.pivot());
        assertEquals(List.of(0.25, 0.75), List.of(m.start(), m.finish()));
        Motion r = parse("sphere { motion { rotate y 30  scale 2 } }").objects().get(0).motion();
        assertEquals(Vec3.Y, r.axis());
        assertEquals(new Vec3(2, 2, 2), r.scale());
    }

    /** The thesis's linear motion; open times are the shutter's, given before or after the object. */
    @Test
    void linearMotionTakesItsTimesFromTheShutter() {
        SceneBuilder b = parse("sphere { motion { direction 2 0 0  speed 3  start 1 } }\nsettings { shutter 0.5 3  samples 4  timesteps 2 }");
        assertEquals(List.of(0.5, 3.0, 2), List.of(b.settings().shutterOpen(), b.settings().shutterClose(), b.settings().timeSteps()));
        Scene s = b.build();
        Motion m = s.objects().get(0).motion();
        assertEquals(List.of(1.0, 3.0), List.of(m.start(), m.finish()));
        assertEquals(new Vec3(6, 0, 0), m.translation()); // speed 3 for 2 units of time along the unit direction
        assertTrue(s.objects().get(0).isMoving());
    }

    @Test
    void csgNodesAndOperandsMove() {
        SceneBuilder b = parse("difference { box { min -1 -1 -1 max 1 1 1 }  sphere { radius 0.5 motion { translate 1 0 0 } }  motion { rotate x 45 } }");
        Bool d = (Bool) b.objects().get(0);
        assertEquals(45, d.motion().degrees(), 1e-12);
        assertNull(d.operands().get(0).motion());
        assertEquals(Vec3.X, d.operands().get(1).motion().translation());
        Bool built = (Bool) b.build().objects().get(0); // the scene's frozen copy
        for (GObject o : built.operands()) assertTrue(o.isMoving(), "an operand of a moving CSG node moves with it");
    }
}
