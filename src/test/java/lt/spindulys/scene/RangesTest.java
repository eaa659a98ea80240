package lt.spindulys.scene;

import lt.spindulys.material.Material;

import static org.junit.jupiter.api.Assertions.*;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.math.Transform;
import lt.spindulys.math.Vec3;
import lt.spindulys.texture.Checker;
import lt.spindulys.texture.TextureImage;

/** The builder API enforces the ranges that keep pixels finite, as the scene parser does. */
class RangesTest {
    private static void refused(String message, Runnable r) {
        IllegalArgumentException e = assertThrows(IllegalArgumentException.class, r::run);
        assertEquals(message, e.getMessage());
    }

    @Test
    void materialRanges() {
        Material.Builder b = Material.builder();
        refused("color must have components between 0 and 100, found (0.0, 101.0, 0.0)", () -> b.color(new Color(0, 101, 0)));
        refused("ka must be between 0 and 10, found 10.5", () -> b.ka(10.5));
        refused("kd must be between 0 and 10, found NaN", () -> b.kd(Double.NaN));
        refused("ks must be between 0 and 10, found Infinity", () -> b.ks(Double.POSITIVE_INFINITY));
        refused("shininess must be between 0 and 1e6, found 1.0E7", () -> b.shininess(1e7));
        refused("kr must be between 0 and 1, found 1.01", () -> b.kr(1.01));
        refused("kt must be between 0 and 1, found -0.1", () -> b.kt(-0.1));
        refused("filter must have components between 0 and 1, found (1.0, 1.5, 1.0)", () -> b.filter(new Color(1, 1.5, 1)));
        refused("beta must have components between 0 and 1e15, found (2.0E15, 2.0E15, 2.0E15)", () -> b.beta(2e15));
        refused("kr + kt must be at most 1, found kr 0.5 + kt 0.6 = 1.1", () -> Material.builder().kr(0.5).kt(0.6).build());
        // The ends of the ranges are allowed, and decimal fractions adding up to 1.
        Material.builder().color(Color.grey(100)).ka(10).kd(10).ks(10).shininess(1e6).kr(0.7).kt(0.3).filter(Color.WHITE).beta(1e15)
                .bumpStrength(-1e15).ior(1e15).build();
    }

    @Test
    void lightAndSettingsRanges() {
        refused("light intensity must be between 0 and 1e15, found 1.0E308", () -> new PointLight(Vec3.ZERO, Color.WHITE, 1e308, PointLight.Falloff.NONE));
        refused("light color must have components between 0 and 100, found (1000.0, 0.0, 0.0)", () -> new PointLight(Vec3.ZERO, new Color(1000, 0, 0)));
        refused("light position must be finite and at most 1e15 in magnitude, found (0.0, 1.0E300, 0.0)", () -> new PointLight(new Vec3(0, 1e300, 0), Color.WHITE));
        refused("ambient must have components between 0 and 100, found (101.0, 101.0, 101.0)", () -> RenderSettings.builder().ambient(Color.grey(101)).build());
        refused("background must have components between 0 and 100, found (0.0, 0.0, Infinity)",
                () -> RenderSettings.builder().background(new Color(0, 0, Double.POSITIVE_INFINITY)).build());
        SceneBuilder sb = new SceneBuilder();
        PointLight max = new PointLight(Vec3.ZERO, Color.grey(100), 1e15, PointLight.Falloff.INVERSE_SQUARE);
        for (int i = 0; i < 1000; i++) sb.light(max);
        assertThrows(IllegalArgumentException.class, () -> sb.light(max));
        assertEquals(1000, sb.lights().size());
    }

    @Test
    void geometryRanges() {
        refused("sphere radius must be a positive number at most 1e15, found 1.0E200", () -> new Sphere(Vec3.ZERO, 1e200));
        assertThrows(IllegalArgumentException.class, () -> new Box(Vec3.ZERO, new Vec3(1, 1e300, 1)));
        assertThrows(IllegalArgumentException.class, () -> new Triangle(Vec3.ZERO, Vec3.X, new Vec3(0, -1e16, 0)));
        refused("transform scales by more than 1e15 (a matrix entry is 1e16)", () -> Transform.scale(1e16, 1, 1));
        refused("transform shrinks by more than a factor of 1e15 (an entry of its inverse is 1e16)", () -> Transform.scale(1, 1, 1e-16));
        refused("transform scales by more than 1e15 (a matrix entry is 1e20)", () -> Transform.scale(1e10, 1e10, 1e10).then(Transform.scale(1e10, 1e10, 1e10)));
        Transform.scale(1e15, 1e15, 1e15).then(Transform.translate(1e15, 0, 0));
        Transform.scale(1e-15, 1e-15, 1e-15).then(Transform.translate(1e15, 0, 0));
        assertTrue(Ranges.isModest(1e15) && Ranges.isModest(-1e15) && !Ranges.isModest(Math.nextUp(1e15)) && !Ranges.isModest(Double.NaN));
    }

    @Test
    void textureRanges() {
        refused("color1 must have components between -100 and 100, found (101.0, 0.0, 0.0)", () -> new Checker(new Color(101, 0, 0), Color.WHITE, 1, false));
        refused("color2 must have components between -100 and 100, found (0.0, -1000.0, 0.0)", () -> new Checker(Color.WHITE, new Color(0, -1000, 0), 1, false));
        new Checker(Color.grey(-100), Color.grey(100), 1, false);
        assertThrows(IllegalArgumentException.class, () -> TextureImage.fromLinear(1, 1, new double[] {0, 1e3, 0}));
        TextureImage.fromLinear(1, 1, new double[] {-100, 100, 0});
    }
}
