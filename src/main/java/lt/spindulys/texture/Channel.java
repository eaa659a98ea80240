package lt.spindulys.texture;

/**
 * The material channels a texture can drive (see docs/scene-format.md, "Textures"). A colour
 * texture's value is used as a colour by DIFFUSE and EMISSION, and as its mean (a scalar) by the
 * others.
 */
public enum Channel {
    /** Multiplies the material's colour C (ambient and diffuse). */
    DIFFUSE,
    /** Multiplies ks. */
    SPECULAR,
    /** Multiplies kr. */
    REFLECTION,
    /** Multiplies kt (refraction and shadows through the object). */
    TRANSPARENCY,
    /** Adds its colour to the light leaving the surface. */
    EMISSION,
    /** A height field, scaled by the material's bump strength, that tilts the shading normal. */
    BUMP;

    /**
     * The scene-language word: the lower-case name.
     *
     * @return the keyword
     */
    public String keyword() { return name().toLowerCase(java.util.Locale.ROOT); }

    /**
     * The channel with this scene-language word.
     *
     * @param word the keyword
     * @return the channel
     */
    public static Channel fromKeyword(String word) {
        for (Channel c : values()) if (c.keyword().equals(word)) return c;
        throw new IllegalArgumentException("unknown texture channel '" + word + "'");
    }

    /**
     * Every scene-language word, in declaration order.
     *
     * @return the keywords
     */
    public static java.util.List<String> keywords() {
        java.util.List<String> out = new java.util.ArrayList<>();
        for (Channel c : values()) out.add(c.keyword());
        return java.util.List.copyOf(out);
    }
}
