package lt.spindulys.texture;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;

import java.awt.image.BufferedImage;
import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;

import javax.imageio.ImageIO;

import org.junit.jupiter.api.Test;

/** The committed texture images are exactly what {@link TextureFiles} generates. */
class TextureFilesTest {
    private static int[] pixels(Path p) throws IOException {
        BufferedImage img = ImageIO.read(p.toFile());
        return img.getRGB(0, 0, img.getWidth(), img.getHeight(), null, 0, img.getWidth());
    }

    private static int[] rgb(int[] argb) {
        int[] out = argb.clone();
        for (int i = 0; i < out.length; i++) out[i] &= 0xffffff;
        return out;
    }

    @Test
    void committedImagesMatchTheGenerator() throws IOException {
        assertArrayEquals(TextureFiles.dice(), rgb(pixels(Path.of("textures/dice.png"))));
        assertArrayEquals(TextureFiles.grid(), rgb(pixels(Path.of("textures/grid.png"))));
        byte[] tga = Files.readAllBytes(Path.of("textures/dice.tga"));
        assertArrayEquals(TextureFiles.tga(TextureFiles.DICE_W, TextureFiles.DICE_H, TextureFiles.dice()), tga);
        assertEquals(18 + TextureFiles.DICE_W * TextureFiles.DICE_H * 3, tga.length);
    }
}
