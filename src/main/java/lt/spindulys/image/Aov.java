package lt.spindulys.image;

import java.nio.file.Path;
import java.util.ArrayList;
import java.util.Collections;
import java.util.EnumSet;
import java.util.List;
import java.util.Set;

/**
 * A render pass (arbitrary output variable) written beside the main image, or as channels of it
 * when it is an OpenEXR file ({@link ExrWriter}). Each but {@link #ALBEDO} is what one extra
 * camera ray through the exact centre of the pixel sees at its first hit (lens centre, time 0),
 * so the values are exact and do not depend on samples per pixel or thread count; except
 * {@link #NOISE}, which records the pixel's own samples.
 */
public enum Aov {
    /** Distance along the unit camera ray to the first hit, +Infinity for the background: one-channel PFM ("Pf"). */
    DEPTH("depth", ".depth.pfm"),
    /** World-space unit shading normal, turned to face the camera ray, 0 0 0 for the background: PFM ("PF"). */
    NORMAL("normal", ".normal.pfm"),
    /** Object id + 1 as a 24-bit integer in 8-bit RGB (R = high byte), 0 for the background: PNG, never sRGB-encoded. */
    OBJECT("object", ".object.png"),
    /**
     * Albedo of the first surface each camera sample hits (its reflectance, textures included,
     * 0 0 0 for the background), averaged over the pixel's samples with the same weights as the
     * colour, so unlike the other passes it is antialiased and shows depth of field and motion
     * blur as the image does: what a denoiser is guided by. PFM ("PF"); in OpenEXR the channels {@code Albedo.R}, {@code Albedo.G} and {@code Albedo.B}.
     */
    ALBEDO("albedo", ".albedo.pfm"),
    /**
     * Adaptive sampling: the samples the pixel took and the estimated relative error of its value
     * when it stopped (0 where one sample leaves nothing to compare): PFM ("PF", R = samples,
     * G = error, B = 0); in OpenEXR the channels {@code Samples.X} and {@code Noise.X}
     * (Blender shows them as the passes Samples and Noise).
     */
    NOISE("noise", ".noise.pfm");

    private final String keyword, suffix;

    Aov(String keyword, String suffix) {
        this.keyword = keyword;
        this.suffix = suffix;
    }

    /**
     * The name in the scene language and on the command line.
     *
     * @return the keyword, for example {@code depth}
     */
    public String keyword() { return keyword; }

    /**
     * What replaces the main output's extension: {@code .depth.pfm}, {@code .normal.pfm}, {@code .object.png}.
     *
     * @return the suffix
     */
    public String suffix() { return suffix; }

    /**
     * The keywords, in declaration order.
     *
     * @return the keywords
     */
    public static List<String> keywords() {
        List<String> k = new ArrayList<>();
        for (Aov a : values()) k.add(a.keyword);
        return List.copyOf(k);
    }

    /**
     * The pass named {@code keyword}.
     *
     * @param keyword the keyword
     * @return the pass
     * @throws IllegalArgumentException "unknown AOV 'x' (expected depth, normal, object, albedo or noise)"
     */
    public static Aov fromKeyword(String keyword) {
        for (Aov a : values()) if (a.keyword.equals(keyword)) return a;
        throw new IllegalArgumentException("unknown AOV '" + keyword + "' (expected " + expected() + ")");
    }

    /**
     * The passes of a comma-separated list such as {@code depth,normal}; at least one, none twice.
     *
     * @param list the list
     * @return the passes, in {@link Aov} order
     * @throws IllegalArgumentException naming the unknown, repeated or empty entry
     */
    public static Set<Aov> parseList(String list) {
        Set<Aov> out = EnumSet.noneOf(Aov.class);
        for (String part : list.split(",", -1)) {
            String name = part.strip();
            if (name.isEmpty()) throw new IllegalArgumentException("empty AOV name in '" + list + "' (expected " + expected() + ")");
            if (!out.add(fromKeyword(name))) throw new IllegalArgumentException("AOV '" + name + "' listed twice");
        }
        return Collections.unmodifiableSet(out);
    }

    /** "depth, normal or object". */
    static String expected() {
        List<String> k = keywords();
        return String.join(", ", k.subList(0, k.size() - 1)) + " or " + k.get(k.size() - 1);
    }

    /**
     * The file of this pass beside {@code mainOutput}: its extension (the last dot and after) is
     * replaced by {@link #suffix()}, so {@code out.png} gives {@code out.depth.pfm}.
     *
     * @param mainOutput the image's path
     * @return the pass's path
     */
    public Path fileBeside(Path mainOutput) {
        String name = mainOutput.getFileName().toString();
        int dot = name.lastIndexOf('.');
        String base = dot > 0 ? name.substring(0, dot) : name;
        return mainOutput.resolveSibling(base + suffix);
    }

    /**
     * The files the passes are written to beside {@code mainOutput} ({@link #fileBeside}), in
     * {@link Aov} order; none for an OpenEXR output, which holds them as channels.
     *
     * @param mainOutput the image's path
     * @param passes the passes
     * @return the files, empty if none are written beside the image
     */
    public static List<Path> filesBeside(Path mainOutput, Set<Aov> passes) {
        if (passes.isEmpty() || ImageFormat.of(mainOutput, "output") == ImageFormat.EXR) return List.of();
        List<Path> files = new ArrayList<>();
        for (Aov a : passes) files.add(a.fileBeside(mainOutput));
        return List.copyOf(files);
    }
}
