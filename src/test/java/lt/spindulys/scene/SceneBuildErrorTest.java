package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Motion;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/** Errors found only when a scene is built name the object: by its source, else by its place in the scene. */
class SceneBuildErrorTest {
    /** Each scale alone is within the ranges (lt.spindulys.math.Ranges); composed they shrink too far. */
    private static final String SINGULAR = "transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e20)";

    /** A union of a box and a sphere, each scaled so that only the composition shrinks too far. */
    private static Bool tinyUnion(Sphere s) {
        s.transform(Transform.scale(1e-10, 1e-10, 1e-10));
        Bool u = new Bool(Bool.Op.UNION, List.of(new Box(Vec3.ZERO, new Vec3(1, 1, 1)), s));
        u.transform(Transform.scale(1e-10, 1e-10, 1e-10));
        return u;
    }

    @Test
    void withoutSourcesObjectsAreNamedByTheirPlace() {
        SceneBuilder b = new SceneBuilder().add(new Sphere(Vec3.ZERO, 1)).add(tinyUnion(new Sphere(Vec3.ZERO, 1)));
        SceneBuildException e = assertThrows(SceneBuildException.class, b::build);
        assertEquals("object 2 (union), operand 2 (sphere): " + SINGULAR, e.getMessage());
        assertEquals(SINGULAR, e.problem());
        assertNull(e.source());
    }

    @Test
    void namesAreShownCut() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.name("n".repeat(1000));
        Bool u = tinyUnion(s);
        u.name("outer");
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(u).build());
        assertEquals("object 1 (union 'outer'), operand 2 (sphere '" + "n".repeat(40) + "...' (1000 characters)): " + SINGULAR, e.getMessage());
    }

    @Test
    void theMessageIsOneLine() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.name("a\nb");
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(tinyUnion(s)).build());
        assertEquals("object 1 (union), operand 2 (sphere 'a\\nb'): " + SINGULAR, e.getMessage());
    }

    @Test
    void theSourceOfTheObjectPlacesTheMessage() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.source("scene.dat:3:3");
        Bool u = tinyUnion(s);
        u.source("scene.dat:1:1");
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(u).build());
        assertEquals("scene.dat:3:3: sphere: " + SINGULAR, e.getMessage());
        assertEquals("scene.dat:3:3", e.source());
    }

    @Test
    void anEnclosingSourcePlacesAnOperandWithoutOne() {
        Bool u = tinyUnion(new Sphere(Vec3.ZERO, 1));
        u.source("scene.dat:1:1");
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(u).build());
        assertEquals("scene.dat:1:1: union, operand 2 (sphere): " + SINGULAR, e.getMessage());
    }

    @Test
    void aMotionOutsideTheShutterIsNamed() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.motion(Motion.translation(new Vec3(1, 0, 0), 2, Double.NaN));
        s.source("m.dat", 4, 1);
        assertEquals("m.dat:4:1", s.source());
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(s).build());
        assertEquals("m.dat:4:1: sphere: motion finish must be after its start, found start 2.0 and finish 1.0 (finish is the shutter close time)",
                e.getMessage());
    }

    @Test
    void sourcesAreKeptAsGiven() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        assertNull(s.source());
        assertEquals("node 'Cube.001'", s.source("node 'Cube.001'").source());
        assertEquals("a.dat:7", s.source("a.dat", 7, 0).source());
        assertNull(s.source(null).source());
        assertThrows(IllegalArgumentException.class, () -> s.source("a.dat", 0, 1));
    }

    @Test
    void aTransformOverflowingWhenComposedIsNamed() {
        Sphere s = new Sphere(Vec3.ZERO, 1);
        s.transform(Transform.scale(1e10, 1e10, 1e10));
        Bool d = new Bool(Bool.Op.DIFFERENCE, List.of(s, new Box(Vec3.ZERO, new Vec3(1, 1, 1))));
        d.transform(Transform.scale(1e10, 1e10, 1e10));
        SceneBuildException e = assertThrows(SceneBuildException.class, () -> new SceneBuilder().add(d).build());
        assertEquals("object 1 (difference), operand 1 (sphere): transform scales by more than 1e15 (a matrix entry is 1e20)", e.getMessage());
    }
}
