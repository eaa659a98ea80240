package lt.spindulys.scene;

import lt.spindulys.math.Color;
import lt.spindulys.math.Vec3;

/**
 * A point light with hard shadows. Its contribution at distance d is color * intensity, divided
 * by d^2 when the falloff is {@link Falloff#INVERSE_SQUARE} (physical) and constant with
 * {@link Falloff#NONE} (the thesis's Whitted model).
 */
public record PointLight(Vec3 position, Color color, double intensity, Falloff falloff) {
    public enum Falloff { NONE, INVERSE_SQUARE }

    public PointLight {
        if (!position.isFinite()) throw new IllegalArgumentException("light position must be finite, found " + position);
        if (!color.isFinite() || !color.isNonNegative()) throw new IllegalArgumentException("light color must have non-negative finite components, found " + color);
        if (!(intensity >= 0) || !Double.isFinite(intensity)) throw new IllegalArgumentException("light intensity must be a non-negative number, found " + intensity);
    }

    public PointLight(Vec3 position, Color color) { this(position, color, 1, Falloff.NONE); }
}
