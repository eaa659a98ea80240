package lt.spindulys.cli;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * A scene that reads a file under every key that names one: a mesh with a material library
 * whose map names an image, a subdivision mesh with an unwrap, a texture image and an
 * environment image. Written into a folder for the tests of outputs and asset folders.
 */
final class SceneFixture {
    private SceneFixture() {}

    /** A 2x2 RGB PNG. */
    static final byte[] PNG = png();

    /** The scene's text, with each file name in {@code names} order replaced from the arguments. */
    static String scene(String mesh, String subdiv, String uv, String image, String environment) {
        return "camera { eye 0 0 -5 lookat 0 0 0 }\n"
                + "texture t { image \"" + image + "\" }\n"
                + "material m { map { texture t channel diffuse } }\n"
                + "mesh { file \"" + mesh + "\" }\n"
                + "subdiv { file \"" + subdiv + "\" uv \"" + uv + "\" level 1 material m }\n"
                + "environment { file \"" + environment + "\" }\n";
    }

    /** The OBJ mesh's text, naming {@code library}. */
    static String obj(String library) {
        return "mtllib " + library + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl a\nf 1 2 3\n";
    }

    /** The material library's text, mapping {@code image}. */
    static String mtl(String image) {
        return "newmtl a\nKd 1 1 1\nmap_Kd " + image + "\n";
    }

    /** Writes the scene and every file it reads into {@code dir}; returns the scene file. */
    static Path write(Path dir) throws IOException {
        Files.createDirectories(dir);
        Files.writeString(dir.resolve("m.obj"), obj("m.mtl"));
        Files.writeString(dir.resolve("m.mtl"), mtl("tex.png"));
        Files.write(dir.resolve("tex.png"), PNG);
        Files.write(dir.resolve("img.png"), PNG);
        Files.write(dir.resolve("sky.png"), PNG);
        Files.copy(Path.of("scenes/models/cube.dat"), dir.resolve("cube.dat"));
        Files.copy(Path.of("scenes/models/cube.tex"), dir.resolve("cube.tex"));
        Path scene = dir.resolve("scene.dat");
        Files.writeString(scene, scene("m.obj", "cube.dat", "cube.tex", "img.png", "sky.png"));
        return scene;
    }

    /** "LINE:COLUMN" of the first occurrence of {@code token} in {@code text}. */
    static String at(String text, String token) {
        int i = text.indexOf(token);
        if (i < 0) throw new IllegalArgumentException(token + " not in the text");
        int line = 1, start = 0;
        for (int k = 0; k < i; k++) {
            if (text.charAt(k) == '\n') {
                line++;
                start = k + 1;
            }
        }
        return line + ":" + (i - start + 1);
    }

    private static byte[] png() {
        java.awt.image.BufferedImage img = new java.awt.image.BufferedImage(2, 2, java.awt.image.BufferedImage.TYPE_INT_RGB);
        img.setRGB(0, 0, 0x804020);
        java.io.ByteArrayOutputStream out = new java.io.ByteArrayOutputStream();
        try {
            javax.imageio.ImageIO.write(img, "png", out);
        } catch (IOException e) {
            throw new java.io.UncheckedIOException(e);
        }
        return out.toByteArray();
    }
}
