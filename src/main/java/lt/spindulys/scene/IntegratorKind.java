package lt.spindulys.scene;

import java.util.ArrayList;
import java.util.List;

/**
 * How light is gathered along a camera ray, by name: the thesis's recursive Whitted tracing, or
 * unidirectional path tracing (global illumination). A user setting (in {@link RenderSettings});
 * the integrators themselves live in {@code lt.spindulys.shading}.
 */
public enum IntegratorKind {
    /**
     * Whitted ray tracing, the thesis's model: ambient, diffuse and Blinn-Phong light from every
     * light, mirror reflection and refraction traced recursively up to {@code maxdepth}.
     */
    WHITTED("whitted"),
    /**
     * Unidirectional path tracing: light sampled at every vertex and combined with the
     * surfaces' own scattering by multiple importance sampling, paths of up to {@code maxdepth}
     * bounces ended early by Russian roulette.
     */
    PATH("path");

    /** The integrator used when none is chosen: the thesis's, so existing scenes render as they always did. */
    public static final IntegratorKind DEFAULT = WHITTED;

    private final String keyword;

    IntegratorKind(String keyword) { this.keyword = keyword; }

    /**
     * The scene-language and command-line word.
     *
     * @return the keyword
     */
    public String keyword() { return keyword; }

    /**
     * The kind with this keyword.
     *
     * @param word the keyword
     * @return the kind
     * @throws IllegalArgumentException naming the keywords accepted
     */
    public static IntegratorKind fromKeyword(String word) {
        for (IntegratorKind k : values()) if (k.keyword.equals(word)) return k;
        throw new IllegalArgumentException("unknown integrator '" + word + "' (expected one of " + String.join(", ", keywords()) + ")");
    }

    /**
     * Every keyword, in declaration order.
     *
     * @return the keywords
     */
    public static List<String> keywords() {
        List<String> out = new ArrayList<>();
        for (IntegratorKind k : values()) out.add(k.keyword);
        return List.copyOf(out);
    }
}
