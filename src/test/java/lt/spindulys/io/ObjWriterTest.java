package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.*;

import java.io.ByteArrayOutputStream;
import java.io.IOException;
import java.nio.charset.StandardCharsets;

import org.junit.jupiter.api.Test;

import lt.spindulys.mesh.MeshData;
import lt.spindulys.subdiv.CatmullClark;
import lt.spindulys.subdiv.RefinedMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.subdiv.Subdivision;

class ObjWriterTest {
    @Test
    void numbersReadBackExactly() {
        // Mesh numbers are at most 1e15 in magnitude (Ranges); the writer's output must read back within that.
        double[] values = {0, -0.0, 1, -3, 0.1, 1e-300, -2.5e14, 123456789012345.0, Math.PI, Double.MIN_VALUE, 1e15, -1e15, Math.nextDown(1e15)};
        for (double d : values) {
            String s = ObjWriter.number(d);
            MeshData m = ObjReader.parse("v " + s + " 0 0\n", "n.obj");
            assertEquals(Double.doubleToLongBits(d), Double.doubleToLongBits(m.positions()[0]), s);
        }
        assertEquals("1", ObjWriter.number(1));
        assertEquals("-0", ObjWriter.number(-0.0));
        assertEquals("0.1", ObjWriter.number(0.1));
    }

    @Test
    void writesCommentsVerticesUvsAndFaces() throws IOException {
        String quad = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\nt hole 1/0/0 0\n";
        RefinedMesh r = CatmullClark.refine(ObjReader.parseSubdiv(quad.replace("t hole 1/0/0 0\n", ""), "q.obj").toControlMesh(), 0);
        ByteArrayOutputStream out = new ByteArrayOutputStream();
        ObjWriter.write(r, false, "two\nlines", out);
        assertEquals("# two\n# lines\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3 4/4\n",
                out.toString(StandardCharsets.UTF_8));

        SubdivInput holed = ObjReader.parseSubdiv(quad, "q.obj");
        out.reset();
        ObjWriter.write(CatmullClark.refine(holed.toControlMesh(), 1), true, null, out);
        String text = out.toString(StandardCharsets.UTF_8);
        assertFalse(text.contains("\nf "), "the only face is a hole: no faces");
        assertTrue(text.contains("\nvn "), "limit normals");
    }

    @Test
    void aRefinedLoopOrBilinearMeshCarriesItsSchemeAndACatmarkOneNone() throws IOException {
        String tris = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3\nf 1 3 4\n";
        for (SubdivOptions.Scheme scheme : SubdivOptions.Scheme.values()) {
            SubdivInput in = ObjReader.parseSubdiv(tris + "t scheme 0/0/1 " + scheme.keyword() + "\n", "t.obj");
            ByteArrayOutputStream out = new ByteArrayOutputStream();
            ObjWriter.write(Subdivision.refine(in.toControlMesh(), 1), false, null, out);
            String text = out.toString(StandardCharsets.UTF_8);
            assertEquals(scheme != SubdivOptions.Scheme.CATMARK, text.contains("t scheme"), text);
            assertEquals(scheme, ObjReader.parseSubdiv(text, "back.obj").options().scheme(), "read back with the scheme it was refined with");
            assertFalse(ObjReader.parse(text, "plain.obj").faceCount() == 0, "a plain OBJ reader skips the tag");
        }
    }
}
