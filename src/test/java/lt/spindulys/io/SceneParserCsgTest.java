package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.List;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ray;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.scene.Bool;
import lt.spindulys.scene.Box;
import lt.spindulys.scene.Cylinder;
import lt.spindulys.scene.GObject;
import lt.spindulys.trace.Hit;
import lt.spindulys.scene.Plane;
import lt.spindulys.scene.Scene;
import lt.spindulys.scene.SceneBuilder;
import lt.spindulys.scene.Sphere;
import lt.spindulys.trace.TraceContext;
import lt.spindulys.scene.TriangleMesh;

/** The union, intersection and difference statements: operands, nesting, common keys, and the grammar's link to Bool. */
class SceneParserCsgTest {
    @TempDir Path dir;

    private GObject only(String scene) {
        SceneBuilder b = SceneParser.parse(scene, "s.dat", dir);
        assertEquals(1, b.objects().size(), "operands are not added to the scene themselves");
        return b.objects().get(0);
    }

    @Test
    void everyOperationHasItsStatementAndBack() {
        List<String> csg = new ArrayList<>();
        for (SceneGrammar.Block b : SceneGrammar.STATEMENTS) if (b.category() == SceneGrammar.Category.CSG) csg.add(b.keyword());
        List<String> ops = new ArrayList<>();
        for (Bool.Op op : Bool.Op.values()) ops.add(op.keyword());
        assertEquals(ops, csg);
        // Only shapes that can bound a volume, and CSG nodes themselves, may be operands.
        assertEquals(List.of("sphere", "plane", "box", "cylinder", "mesh", "subdiv", "union", "intersection", "difference"),
                SceneGrammar.operandNames());
    }

    @Test
    void operandsInOrderNestedToAnyDepth() {
        GObject o = only("""
                difference {
                  box { min -1 -1 -1  max 1 1 1 }
                  union {
                    sphere { radius 0.5 }
                    intersection {
                      cylinder { base 0 0 0  top 0 2 0  radius 0.2 }
                      plane { normal 0 1 0  offset 1.5 }
                    }
                  }
                  sphere { center 1 1 1  radius 0.3 }
                }
                """);
        Bool d = assertInstanceOf(Bool.class, o);
        assertEquals(Bool.Op.DIFFERENCE, d.op());
        assertEquals(3, d.operands().size());
        assertInstanceOf(Box.class, d.operands().get(0));
        Bool u = assertInstanceOf(Bool.class, d.operands().get(1));
        assertEquals(Bool.Op.UNION, u.op());
        assertEquals(0.5, assertInstanceOf(Sphere.class, u.operands().get(0)).radius());
        Bool i = assertInstanceOf(Bool.class, u.operands().get(1));
        assertEquals(Bool.Op.INTERSECTION, i.op());
        assertInstanceOf(Cylinder.class, i.operands().get(0));
        assertEquals(1.5, assertInstanceOf(Plane.class, i.operands().get(1)).offset());
        assertEquals(new Vec3(1, 1, 1), assertInstanceOf(Sphere.class, d.operands().get(2)).center());
    }

    @Test
    void commonKeysOnTheNodeAndOnEachOperandMixedWithOperands() {
        GObject o = only("""
                material m { color 1 0 0 }
                union {
                  translate 1 0 0
                  sphere { radius 2  material { color 0 1 0 }  scale 2  name "inner" }
                  material m
                  rotate y 90
                  box { min 0 0 0  max 1 1 1  rotate x 10  translate 0 1 0 }
                  name "both"
                  scale 3
                }
                """);
        Bool u = assertInstanceOf(Bool.class, o);
        assertEquals("both", u.name());
        assertEquals(new Color(1, 0, 0), u.material().color());
        assertEquals(Transform.translate(1, 0, 0).then(Transform.rotateY(90)).then(Transform.scale(3, 3, 3)), u.transform());
        GObject s = u.operands().get(0), b = u.operands().get(1);
        assertEquals("inner", s.name());
        assertEquals(new Color(0, 1, 0), s.material().color());
        assertEquals(Transform.scale(2, 2, 2), s.transform());
        assertNull(b.material(), "an operand without a material inherits at freeze");
        assertEquals(Transform.rotate(Vec3.X, 10).then(Transform.translate(0, 1, 0)), b.transform());
    }

    @Test
    void aClosedMeshIsAnOperand() throws IOException {
        Files.writeString(dir.resolve("tet.obj"), "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
        Bool i = assertInstanceOf(Bool.class, only("intersection { mesh { file \"tet.obj\" } sphere { } }"));
        assertInstanceOf(TriangleMesh.class, i.operands().get(0));
    }

    /** The parsed node is the solid the operation says: a ray down the axis of a drilled box. */
    @Test
    void theParsedDifferenceIsHollowWhereTheCutterWas() {
        SceneBuilder b = SceneParser.parse("""
                difference {
                  box { min -1 -1 -1  max 1 1 1 }
                  cylinder { base 0 0 -2  top 0 0 0  radius 0.5 }
                  translate 0 0 3
                }
                """, "s.dat", dir);
        Scene scene = b.build();
        TraceContext ctx = new TraceContext();
        Hit hit = new Hit();
        // Straight into the drilled hole: the first surface is the hole's bottom at z = 3 (the cylinder's top cap, flipped).
        Ray r = new Ray(new Vec3(0, 0, -5), Vec3.Z);
        assertTrue(scene.intersect(r, hit, ctx));
        assertEquals(8, hit.t, 1e-9);
        assertInstanceOf(Cylinder.class, hit.object);
        assertTrue(hit.flipNormal);
        // Beside the hole: the box's front face at z = 2.
        Ray side = new Ray(new Vec3(0.7, 0, -5), Vec3.Z);
        assertTrue(scene.intersect(side, hit.reset(Double.POSITIVE_INFINITY), ctx));
        assertEquals(7, hit.t, 1e-9);
        assertInstanceOf(Box.class, hit.object);
        assertFalse(hit.flipNormal);
    }
}
