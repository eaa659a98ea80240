package lt.spindulys.scene;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertSame;

import java.util.List;

import org.junit.jupiter.api.Test;

import lt.spindulys.io.ObjReader;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Motion;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;

/** Every builder method of every shape returns that shape, so a chain needs no cast. */
class BuilderMethodTypesTest {
    @Test
    void builderMethodsKeepTheObjectsType() {
        // Compiles only if every builder method of every shape returns that shape.
        Material red = Material.builder().color(new Color(0.9, 0.2, 0.1)).build();
        Transform t = Transform.translate(1, 0, 0);
        Motion m = Motion.linear(Vec3.Y, 1, 0, 1);
        Sphere sphere = new Sphere(Vec3.ZERO, 1).material(red).transform(t).motion(m).name("s").source("f.dat").source("f.dat", 1, 2);
        Plane plane = new Plane(Vec3.Y, 0).material(red).transform(t).motion(m).name("p").source("f.dat").source("f.dat", 1, 2);
        Box box = new Box(Vec3.ZERO, new Vec3(1, 1, 1)).material(red).transform(t).motion(m).name("b").source("f.dat").source("f.dat", 1, 2);
        Cylinder cylinder = new Cylinder(Vec3.ZERO, Vec3.Y, 1).material(red).transform(t).motion(m).name("c").source("f.dat").source("f.dat", 1, 2);
        Triangle triangle = new Triangle(Vec3.ZERO, Vec3.X, Vec3.Y).material(red).transform(t).motion(m).name("t").source("f.dat").source("f.dat", 1, 2);
        TriangleMesh mesh = new TriangleMesh(TestMeshes.cube()).material(red).transform(t).motion(m).name("m").source("f.dat").source("f.dat", 1, 2);
        SubdivisionSurface surface = new SubdivisionSurface(ObjReader.parseSubdiv(TestMeshes.CUBE_OBJ, "cube.obj").toControlMesh(), 1)
                .material(red).transform(t).motion(m).name("d").source("f.dat").source("f.dat", 1, 2);
        Bool bool = new Bool(Bool.Op.UNION, List.of(sphere, box)).material(red).transform(t).motion(m).name("u").source("f.dat").source("f.dat", 1, 2);
        for (GObject o : List.<GObject>of(sphere, plane, box, cylinder, triangle, mesh, surface, bool)) {
            assertSame(red, o.material());
            assertEquals(t, o.transform());
            assertSame(m, o.motion());
            assertEquals("f.dat:1:2", o.source());
        }
    }
}
