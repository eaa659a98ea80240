package lt.spindulys.viewer;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertFalse;
import static org.junit.jupiter.api.Assertions.assertNull;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.List;
import java.util.Map;
import java.util.stream.Stream;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.api.io.TempDir;

import lt.spindulys.frontend.FailureMessage;

class PluginFormTest {
    @TempDir
    Path dir;

    private PluginForm form() {
        return new PluginForm(new FakePlugin(), Fixtures.surfaces(), Fixtures.view(48, 30), dir);
    }

    @Test
    void startsAtTheDefaultsWithTheOutputNamedAfterTheFirstSurface() {
        PluginForm f = form();
        assertEquals("48", f.value("size"), "the plugin's default depends on the view");
        assertEquals("0 1 0", f.value("color"));
        assertEquals(dir.resolve("cube.png").toString(), f.output());
        assertNull(f.problem());
        assertTrue(f.valid());
        assertEquals(List.of("Image", "cube.obj", "torus.dat"), List.copyOf(f.groups().keySet()));
        assertEquals(List.of("surface.1.material"), f.groups().get("torus.dat").stream().map(o -> o.key()).toList());
    }

    @Test
    void anInvalidValueIsNamedInOneLine() {
        PluginForm f = form();
        f.set("size", "0");
        assertEquals("Size (size) must be between 1 and 256, found 0", f.problem());
        assertFalse(f.valid());
        f.set("size", "12");
        f.set("color", "1 2\n3");
        assertEquals("Colour (color) must be three numbers r g b between 0 and 1, found '1 2\\n3'", f.problem());
        assertEquals(f.problem(), assertThrows(IllegalArgumentException.class, f::accept).getMessage());
        f.set("color", "1 0 0");
        assertNull(f.problem());
        assertThrows(IllegalArgumentException.class, () -> f.set("nosuch", "1"));
    }

    @Test
    void theOutputMustHaveAnExtensionOfThePluginAndAnExistingFolder() throws IOException {
        PluginForm f = form();
        f.setOutput("  ");
        assertEquals("Output file: give the file to write (.png)", f.problem());
        f.setOutput(dir.resolve("picture.jpg").toString());
        assertEquals("Output file: Fake painter writes .png files, found 'picture.jpg'", f.problem());
        Path missing = dir.resolve("missing").resolve("picture.png");
        f.setOutput(missing.toString());
        assertEquals("cannot write '" + missing + "': directory '" + missing.getParent() + "' does not exist", f.problem());
        Path file = Files.writeString(dir.resolve("file"), "x");
        f.setOutput(file.resolve("picture.png").toString());
        assertEquals("cannot write '" + file.resolve("picture.png") + "': '" + file + "' is not a directory", f.problem());
        Path folder = Files.createDirectory(dir.resolve("folder.png"));
        f.setOutput(folder.toString());
        assertEquals("cannot write '" + folder + "': it is a directory", f.problem());
        f.setOutput(dir.resolve("Picture.PNG").toString());
        assertNull(f.problem(), "extensions are compared without case");
    }

    @Test
    void acceptChecksThatAFileCanBeCreatedAndLeavesNone() throws IOException {
        PluginForm f = form();
        f.set("size", "7");
        PluginForm.Accepted a = f.accept();
        assertEquals(dir.resolve("cube.png"), a.output());
        assertEquals("7", a.values().get("size"));
        assertEquals(f.options().size(), a.values().size());
        try (Stream<Path> left = Files.list(dir)) {
            assertEquals(List.of(), left.toList(), "the trial file is removed again");
        }
        // Creating files is refused in /proc even for root, so this holds whoever runs the test.
        if (Files.isDirectory(Path.of("/proc/self"))) {
            f.setOutput("/proc/picture.png");
            assertNull(f.problem(), "the folder exists, so the live check lets it pass");
            IOException e = assertThrows(IOException.class, f::accept);
            assertTrue(e.getMessage().startsWith("cannot write '/proc/picture.png': cannot create a file in '/proc': "), e.getMessage());
            assertEquals("render: " + e.getMessage(), FailureMessage.of(e));
        }
    }

    @Test
    void nothingDisplayedOrARejectedSurfaceIsOneLine() {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class,
                () -> new PluginForm(new FakePlugin(), List.of(), Fixtures.view(4, 4), dir));
        assertEquals(PluginForm.NO_SURFACE, e.getMessage());
        FakePlugin twice = new FakePlugin() {
            @Override public List<lt.spindulys.plugin.PluginOption> options(List<lt.spindulys.plugin.DisplayedSurface> s, lt.spindulys.plugin.PluginView v) {
                return List.of(lt.spindulys.plugin.PluginOption.integer("n", "N", "A", 1, 0, 2, "n"),
                        lt.spindulys.plugin.PluginOption.integer("n", "N", "B", 1, 0, 2, "n"));
            }
        };
        assertEquals("plugin Fake painter gives option 'n' twice",
                assertThrows(IllegalArgumentException.class, () -> new PluginForm(twice, Fixtures.surfaces(), Fixtures.view(4, 4), dir)).getMessage());
    }

    @Test
    void theDefaultNameIsAFileNameWhateverTheSurfaceIsCalled() {
        assertEquals("cube.jpg", PluginForm.defaultFileName("cube.obj", "jpg"));
        assertEquals("cube.jpg", PluginForm.defaultFileName("/meshes/cube.obj", "jpg"));
        assertEquals("a_b_c.png", PluginForm.defaultFileName("a:b*c", "png"));
        assertEquals("surface.png", PluginForm.defaultFileName("..", "png"));
        assertEquals(".hidden.png", PluginForm.defaultFileName(".hidden", "png"));
        assertEquals("tga", PluginForm.extension("x.TGA"));
        assertEquals("", PluginForm.extension(".png"));
    }

    @Test
    void acceptedValuesAreACopy() {
        java.util.HashMap<String, String> m = new java.util.HashMap<>(Map.of("a", "1"));
        PluginForm.Accepted a = new PluginForm.Accepted(m, dir.resolve("x.png"));
        m.put("a", "2");
        assertEquals("1", a.values().get("a"));
    }

    @Test
    void fieldsThatDoNotMatterForTheChosenMaterialAreToldApart() {
        PluginForm f = new PluginForm(new lt.spindulys.plugin.raytrace.RayTracePlugin(), Fixtures.surfaces(), Fixtures.view(48, 30), dir);
        assertEquals("opaque", f.value("surface.0.material"));
        assertTrue(f.applies("surface.0.color"));
        assertFalse(f.applies("surface.0.ior"), "no index of refraction for an opaque surface");
        assertFalse(f.applies("surface.0.reflectivity"));
        assertTrue(f.applies("samples"), "unconditional");
        f.set("surface.0.material", "transparent");
        assertTrue(f.applies("surface.0.ior"));
        assertTrue(f.applies("surface.0.tint"));
        assertFalse(f.applies("surface.0.color"), "a transparent surface is coloured by its tint");
        f.set("surface.0.material", "mirror");
        assertTrue(f.applies("surface.0.reflectivity"));
        assertTrue(f.applies("surface.0.color"));
        assertFalse(f.applies("surface.0.attenuation"));
    }
}
