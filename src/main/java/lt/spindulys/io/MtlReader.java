package lt.spindulys.io;

import java.io.IOException;
import java.nio.charset.StandardCharsets;
import java.nio.file.InvalidPathException;
import java.nio.file.NoSuchFileException;
import java.nio.file.Path;
import java.util.ArrayList;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Locale;
import java.util.Map;

import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.limits.MessageText;
import lt.spindulys.material.Material;
import lt.spindulys.math.Color;
import lt.spindulys.math.Ranges;
import lt.spindulys.texture.Channel;
import lt.spindulys.texture.Dissolve;
import lt.spindulys.texture.Filter;
import lt.spindulys.texture.ImageTexture;
import lt.spindulys.texture.Texture;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.Uniform;
import lt.spindulys.texture.Uv;
import lt.spindulys.texture.Wrap;

/**
 * Reads Wavefront material libraries ({@code .mtl}) into named {@link Material}s, through the
 * public material builder: of the Whitted model, or of the principled one when a material gives
 * any of the physically based extension's {@code Pr}, {@code Pm}, {@code map_Pr} or
 * {@code map_Pm} (below). The statements read, and how each maps to the Whitted model
 * (docs/scene-format.md, "OBJ materials", says the same for users):
 * <ul>
 * <li>{@code newmtl NAME} starts a material (the name is the rest of the line);</li>
 * <li>{@code Kd} is the colour C, with kd 1 (default 0.8 0.8 0.8);</li>
 * <li>{@code Ka}: the ambient term is ka·Ia·C, so ka is the mean of Ka (the hue is Kd's);
 *     without Ka, ka is the model's default 0.1;</li>
 * <li>{@code Ks}: ks is its mean (highlights take the light's colour: the model has no
 *     specular colour); with a reflecting illum, kr is the same mean;</li>
 * <li>{@code Ns} is the Blinn-Phong exponent as it is (0 to 10^6);</li>
 * <li>{@code d} (dissolve, opacity) and {@code Tr} (1 − d) give kt = 1 − d; {@code Tf} is the
 *     transmission filter;</li>
 * <li>{@code Ni} is the index of refraction, used by the refracting illum models 6 and 7;</li>
 * <li>{@code Ke} is an emitted colour (a uniform texture on the emission channel);</li>
 * <li>{@code illum} 0 to 9 says which terms are on: 0 the colour Kd as it is (emitted, unlit),
 *     1 ambient and diffuse, 2 (the default) with the highlight, 3 to 9 with reflection (kr
 *     the mean of Ks, at most 1 − kt), 5 and 7 with Fresnel, 6 and 7 refracting with ior Ni;
 *     10 is refused;</li>
 * <li>{@code map_Kd}, {@code map_Ks}, {@code map_d}, {@code map_Bump} (or {@code bump}) bind
 *     image textures to the diffuse, specular, transparency and bump channels through the mesh's
 *     UVs, with the options {@code -o}, {@code -s}, {@code -clamp} and (bump only) {@code -bm}.</li>
 * </ul>
 * A physically based material ({@link Material.Model#PRINCIPLED}) takes {@code Kd} as its base
 * colour (0 to 1), {@code Pr} as roughness and {@code Pm} as metallic (0 to 1; without them 0.5
 * and 0, or 1 when {@code map_Pr} or {@code map_Pm} binds an image to the roughness or metallic
 * channel, so that the image gives the value), {@code Ke} as its emission, 1 − d as
 * transmission (as kt above, {@code map_d} included), {@code Ni} as ior (default 1.5; above 0),
 * {@code Tf} as filter, and {@code map_Kd} and {@code map_Bump} as above. The Whitted statements
 * {@code Ka}, {@code Ks}, {@code Ns}, {@code illum} and {@code map_Ks} are read and checked but
 * not used: exporters write them beside the extension's keys, and the principled parameters
 * take their place.
 * Keywords are matched without regard to case ({@code map_kd} as {@code map_Kd}). Anything else,
 * an option not listed, a key given twice for one material, or a value out of range is an error
 * naming file:line:column, what was found and what was expected. Texture files are resolved
 * relative to the library's folder and loaded through the scene's {@link TextureCache}.
 */
public final class MtlReader {
    private MtlReader() {}

    /** Bytes of heap per byte of the file while it is parsed (the bytes, the decoded text, the lines). */
    private static final int HEAP_PER_BYTE = 6;

    /**
     * Reads a material library.
     *
     * @param file the .mtl file
     * @param textures the cache through which texture images are loaded
     * @return the materials by name, in the order defined
     * @throws SceneException naming file:line:column for malformed input, a missing file or texture
     */
    public static Map<String, Material> read(Path file, TextureCache textures) {
        return read(file, textures, new AssetGate(AssetRoots.ANY));
    }

    /** {@link #read(Path, TextureCache)}, its texture maps passing {@code gate} before they are opened. */
    static Map<String, Material> read(Path file, TextureCache textures, AssetGate gate) {
        String name = file.toString();
        String problem = InputFiles.problem(file);
        if (problem != null) throw new SceneException(name, 0, 0, "material library " + problem + " (looked in " + file.toAbsolutePath().normalize() + ")");
        byte[] bytes;
        try {
            bytes = InputFiles.readAllBytes(file, "material library", HEAP_PER_BYTE);
        } catch (InsufficientMemoryException e) {
            throw new SceneException(name, 0, 0, e.getMessage(), e);
        } catch (NoSuchFileException e) {
            throw new SceneException(name, 0, 0, "material library not found (looked in " + file.toAbsolutePath().normalize() + ")");
        } catch (IOException e) {
            throw new SceneException(name, 0, 0, "cannot read material library: " + e.getMessage(), e);
        }
        Path folder = file.toAbsolutePath().getParent();
        return new Parser(new String(bytes, StandardCharsets.UTF_8), name, folder, textures, gate).run();
    }

    /**
     * Parses material library text.
     *
     * @param text the file's content
     * @param fileName the name for messages
     * @param folder the folder texture file names are relative to
     * @param textures the cache through which texture images are loaded
     * @return the materials by name, in the order defined
     * @throws SceneException naming file:line:column for malformed input or a missing texture
     */
    public static Map<String, Material> parse(String text, String fileName, Path folder, TextureCache textures) {
        return new Parser(text, fileName, folder, textures, new AssetGate(AssetRoots.ANY)).run();
    }

    /** The statements read, as the format spells them, in documentation order. */
    static final List<String> KEYS = List.of("newmtl", "Kd", "Ka", "Ks", "Ns", "d", "Tr", "Tf", "Ni", "Ke", "illum",
            "map_Kd", "map_Ks", "map_d", "map_Bump", "bump", "Pr", "Pm", "map_Pr", "map_Pm");
    /** {@link #KEYS} in lower case, as keywords are matched. */
    private static final List<String> LOWER_KEYS = KEYS.stream().map(k -> k.toLowerCase(Locale.ROOT)).toList();

    /** Statements of the format that are known but not supported, with why. */
    private static String unsupported(String key) {
        return switch (key) {
            case "map_ka" -> "the diffuse map, map_Kd, also drives the ambient term";
            case "map_ns", "map_ke", "map_tr", "disp", "decal", "refl", "norm", "map_aat", "sharpness" -> "this renderer has no such channel";
            case "ps", "pc", "pcr", "aniso", "anisor", "map_ps" -> "the principled material has no sheen, clearcoat or anisotropy; of the physically based keys Pr, Pm, map_Pr and map_Pm are read";
            default -> null;
        };
    }

    /** Tokens of a line looked at: more than the longest statement (a map with every option) has. */
    private static final int MAX_TOKENS = 32;

    /** The options a map statement takes: -o, -s, -clamp, and -bm on bump maps. */
    private static final List<String> OPTIONS = List.of("-o", "-s", "-clamp", "-bm");

    /** One material's statements as read, with where each key was first given. */
    private static final class Spec {
        final String name;
        final int line;
        Color kd, ka, ks, tf, ke;
        double ns = Double.NaN, d = Double.NaN, ni = Double.NaN, pr = Double.NaN, pm = Double.NaN;
        int illum = -1;
        MapSpec map, mapKs, mapD, mapBump, mapPr, mapPm;
        final Map<String, Integer> given = new java.util.HashMap<>();

        Spec(String name, int line) {
            this.name = name;
            this.line = line;
        }
    }

    /** A texture statement: the texture, its mapping (scale and offset), and the bump multiplier. */
    private record MapSpec(Texture texture, Uv mapping, double bm) {}

    /** A token of a line: its text and where it starts (0-based index into the line, 1-based column). */
    private record Tok(String text, int index, int column) {}

    private static final class Parser {
        private final String text, file;
        private final Path folder;
        private final TextureCache textures;
        private final AssetGate gate;
        private final Library out = new Library();
        private int line;
        private String current;

        Parser(String text, String file, Path folder, TextureCache textures, AssetGate gate) {
            this.text = text;
            this.file = file;
            this.folder = folder;
            this.textures = textures;
            this.gate = gate;
        }

        /** The materials made so far, by name, with the line each was defined on. */
        private static final class Library {
            final LinkedHashMap<String, Material> materials = new LinkedHashMap<>();
            final Map<String, Integer> lines = new java.util.HashMap<>();
        }

        Map<String, Material> run() {
            Spec spec = null;
            int at = 0, n = text.length();
            // A UTF-8 byte order mark is not part of the first statement.
            if (n > 0 && text.charAt(0) == '\uFEFF') at = 1;
            line = 0;
            while (at <= n) {
                int e = at;
                while (e < n && text.charAt(e) != '\n' && text.charAt(e) != '\r') e++;
                line++;
                String raw = text.substring(at, e);
                int hash = raw.indexOf('#');
                String content = hash >= 0 ? raw.substring(0, hash) : raw;
                current = content;
                List<Tok> toks = tokens(content);
                if (!toks.isEmpty()) spec = statement(spec, toks);
                if (e < n && text.charAt(e) == '\r' && e + 1 < n && text.charAt(e + 1) == '\n') e++;
                at = e + 1;
            }
            if (spec != null) finish(spec);
            return java.util.Collections.unmodifiableMap(out.materials);
        }

        private Spec statement(Spec spec, List<Tok> toks) {
            Tok kw = toks.get(0);
            String key = kw.text().toLowerCase(Locale.ROOT);
            if (key.equals("newmtl")) {
                if (toks.size() < 2) throw error(kw.column() + kw.text().length(), "expected a material name after 'newmtl', found end of line");
                String name = rest(toks.get(1));
                Integer first = out.lines.get(name);
                if (first != null || spec != null && spec.name.equals(name)) {
                    throw error(toks.get(1).column(), "material " + MessageText.quote(name) + " defined twice (first on line " + (first != null ? first : spec.line) + ")");
                }
                if (spec != null) finish(spec);
                return new Spec(name, line);
            }
            if (!LOWER_KEYS.contains(key)) {
                String why = unsupported(key);
                if (why != null) throw error(kw.column(), "'" + kw.text() + "' is not supported (" + why + "); supported: " + keyList());
                String near = SceneGrammar.nearest(key, LOWER_KEYS);
                throw error(kw.column(), "unknown material statement " + MessageText.quote(kw.text())
                        + (near == null ? "" : " (did you mean '" + KEYS.get(LOWER_KEYS.indexOf(near)) + "'?)") + " (supported: " + keyList() + ")");
            }
            if (spec == null) throw error(kw.column(), "'" + kw.text() + "' before any 'newmtl' (a material's statements follow its newmtl line)");
            Integer earlier = spec.given.putIfAbsent(key.equals("tr") ? "d" : key.equals("bump") ? "map_bump" : key, line);
            if (earlier != null) {
                throw error(kw.column(), "'" + kw.text() + "' given twice for material " + MessageText.quote(spec.name) + " (first on line " + earlier + ")"
                        + (key.equals("d") || key.equals("tr") ? "; Tr is 1 - d, give one of them" : ""));
            }
            switch (key) {
                case "kd" -> spec.kd = colour(toks, Ranges.MAX_COLOUR);
                case "ka" -> spec.ka = colour(toks, Ranges.MAX_COEFFICIENT);
                case "ks" -> spec.ks = colour(toks, Ranges.MAX_COEFFICIENT);
                case "tf" -> spec.tf = colour(toks, 1);
                case "ke" -> spec.ke = colour(toks, Ranges.MAX_COLOUR);
                case "ns" -> spec.ns = single(toks, 0, Ranges.MAX_SHININESS);
                case "d" -> {
                    if (toks.size() > 1 && toks.get(1).text().equalsIgnoreCase("-halo")) {
                        throw error(toks.get(1).column(), "'d -halo' is not supported (a dissolve that depends on the viewing angle); give d alone");
                    }
                    spec.d = single(toks, 0, 1);
                }
                case "tr" -> spec.d = 1 - single(toks, 0, 1);
                case "ni" -> spec.ni = single(toks, 0, Ranges.MAX_NUMBER);
                case "illum" -> spec.illum = illum(toks);
                case "map_kd" -> spec.map = map(toks, false);
                case "map_ks" -> spec.mapKs = map(toks, false);
                case "map_d" -> spec.mapD = map(toks, false);
                case "map_bump", "bump" -> spec.mapBump = map(toks, true);
                case "pr" -> spec.pr = single(toks, 0, 1);
                case "pm" -> spec.pm = single(toks, 0, 1);
                case "map_pr" -> spec.mapPr = map(toks, false);
                case "map_pm" -> spec.mapPm = map(toks, false);
                default -> throw new IllegalStateException("material key without a handler: " + key);
            }
            return spec;
        }

        private static String keyList() {
            return String.join(", ", KEYS);
        }

        /** The material of a complete spec, through the builder; refusals are reported at the newmtl line. */
        private void finish(Spec s) {
            if (!Double.isNaN(s.pr) || !Double.isNaN(s.pm) || s.mapPr != null || s.mapPm != null) {
                finishPrincipled(s);
                return;
            }
            Material.Builder b = Material.builder().name(s.name);
            Color kd = s.kd != null ? s.kd : Color.grey(0.8);
            int illum = s.illum >= 0 ? s.illum : 2;
            double ks = s.ks != null ? mean(s.ks) : 0;
            double opacity = Double.isNaN(s.d) ? 1 : s.d;
            boolean reflects = illum >= 3 && illum <= 9;
            boolean refracts = illum == 6 || illum == 7;
            double kt = s.mapD != null ? 1 : 1 - opacity;
            try {
                if (illum == 0) {
                    // Constant colour: Kd shown as it is, lit or not.
                    if (s.ke != null || s.given.containsKey("map_kd")) {
                        int at = s.ke != null ? s.given.get("ke") : s.given.get("map_kd");
                        throw new SceneException(file, at, 1, "illum 0 (a constant colour, Kd) cannot have " + (s.ke != null ? "Ke" : "map_Kd")
                                + ": give illum 1 or 2 for a lit surface");
                    }
                    b.color(kd).ka(0).kd(0).ks(0).texture(Channel.EMISSION, new Uniform(kd), new Uv(1, 1));
                } else {
                    b.color(kd).kd(1);
                    if (s.ka != null) b.ka(mean(s.ka));
                    b.ks(illum >= 2 ? ks : 0);
                }
                if (!Double.isNaN(s.ns)) b.shininess(s.ns);
                b.kt(kt);
                if (reflects) b.kr(Math.max(0, Math.min(ks, 1 - kt)));
                if (refracts) {
                    double ni = Double.isNaN(s.ni) ? 1 : s.ni;
                    if (!(ni > 0)) {
                        throw new SceneException(file, s.given.get("ni"), 1, "Ni must be above 0 for illum " + illum + " (it refracts), found " + ni);
                    }
                    b.ior(ni);
                }
                b.fresnel(illum == 5 || illum == 7);
                if (s.tf != null) b.filter(s.tf);
                if (s.ke != null && !s.ke.isBlack()) b.texture(Channel.EMISSION, new Uniform(s.ke), new Uv(1, 1));
                if (s.map != null) b.texture(Channel.DIFFUSE, s.map.texture(), s.map.mapping());
                if (s.mapKs != null) b.texture(Channel.SPECULAR, s.mapKs.texture(), s.mapKs.mapping());
                if (s.mapD != null) b.texture(Channel.TRANSPARENCY, new Dissolve(s.mapD.texture(), opacity), s.mapD.mapping());
                if (s.mapBump != null) b.texture(Channel.BUMP, s.mapBump.texture(), s.mapBump.mapping()).bumpStrength(s.mapBump.bm());
                out.materials.put(s.name, b.build());
                out.lines.put(s.name, s.line);
            } catch (IllegalArgumentException e) {
                throw new SceneException(file, s.line, 1, "material " + MessageText.quote(s.name) + ": " + e.getMessage());
            }
        }

        /**
         * The principled material of a spec with physically based keys (see the class comment);
         * refusals are reported at the statement that gave the value, else at the newmtl line.
         */
        private void finishPrincipled(Spec s) {
            Material.Builder b = Material.builder().name(s.name).model(Material.Model.PRINCIPLED);
            if (s.kd != null && s.kd.max() > 1) {
                throw new SceneException(file, s.given.get("kd"), 1, "Kd must be between 0 and 1 for a physically based material (Pr, Pm), found "
                        + s.kd + ": a base colour is a reflectance");
            }
            if (s.given.containsKey("ni") && !(s.ni > 0)) {
                throw new SceneException(file, s.given.get("ni"), 1, "Ni must be above 0 for a physically based material (Pr, Pm), found " + s.ni);
            }
            double opacity = Double.isNaN(s.d) ? 1 : s.d;
            try {
                b.color(s.kd != null ? s.kd : Color.grey(0.8));
                // A map alone gives the value: the channel multiplies the material's by the map.
                if (!Double.isNaN(s.pr) || s.mapPr != null) b.roughness(Double.isNaN(s.pr) ? 1 : s.pr);
                if (!Double.isNaN(s.pm) || s.mapPm != null) b.metallic(Double.isNaN(s.pm) ? 1 : s.pm);
                b.transmission(s.mapD != null ? 1 : 1 - opacity);
                if (s.given.containsKey("ni")) b.ior(s.ni);
                if (s.tf != null) b.filter(s.tf);
                if (s.ke != null) b.emission(s.ke);
                if (s.map != null) b.texture(Channel.DIFFUSE, s.map.texture(), s.map.mapping());
                if (s.mapD != null) b.texture(Channel.TRANSPARENCY, new Dissolve(s.mapD.texture(), opacity), s.mapD.mapping());
                if (s.mapBump != null) b.texture(Channel.BUMP, s.mapBump.texture(), s.mapBump.mapping()).bumpStrength(s.mapBump.bm());
                if (s.mapPr != null) b.texture(Channel.ROUGHNESS, s.mapPr.texture(), s.mapPr.mapping());
                if (s.mapPm != null) b.texture(Channel.METALLIC, s.mapPm.texture(), s.mapPm.mapping());
                out.materials.put(s.name, b.build());
                out.lines.put(s.name, s.line);
            } catch (IllegalArgumentException e) {
                throw new SceneException(file, s.line, 1, "material " + MessageText.quote(s.name) + ": " + e.getMessage());
            }
        }

        private static double mean(Color c) { return (c.r() + c.g() + c.b()) / 3; }

        /** illum 0..9: which terms are on. */
        private int illum(List<Tok> toks) {
            Tok t = value(toks, 1, "an illumination model 0 to 9 for 'illum'");
            int v;
            try {
                v = Integer.parseInt(t.text());
            } catch (NumberFormatException e) {
                throw error(t.column(), "expected an illumination model 0 to 9 for 'illum', found " + MessageText.quote(t.text()));
            }
            if (v == 10) throw error(t.column(), "illum 10 (shadows cast onto invisible surfaces) is not supported; expected 0 to 9");
            if (v < 0 || v > 10) throw error(t.column(), "expected an illumination model 0 to 9 for 'illum', found " + v);
            end(toks, 2, "the illumination model");
            return v;
        }

        /** One number in lo..hi after the key. */
        private double single(List<Tok> toks, double lo, double hi) {
            String key = toks.get(0).text();
            double v = number(value(toks, 1, "a number for '" + key + "'"), key, lo, hi);
            end(toks, 2, "the value of '" + key + "'");
            return v;
        }

        /** r, or r g b (r alone is grey), each 0..max. */
        private Color colour(List<Tok> toks, double max) {
            String key = toks.get(0).text();
            Tok first = value(toks, 1, "1 or 3 numbers for '" + key + "'");
            String w = first.text().toLowerCase(Locale.ROOT);
            if (w.equals("spectral") || w.equals("xyz")) {
                throw error(first.column(), "'" + key + " " + first.text() + "' is not supported; give r g b (or one number for grey)");
            }
            double r = number(first, key, 0, max);
            if (toks.size() == 2) return Color.grey(r);
            if (toks.size() != 4) {
                Tok bad = toks.size() == 3 ? null : toks.get(4);
                if (bad != null) throw error(bad.column(), "unexpected " + MessageText.quote(bad.text()) + " after the colour of '" + key + "' (expected 1 or 3 numbers)");
                throw error(current.length() + 1, "expected 1 or 3 numbers for '" + key + "', found 2");
            }
            return new Color(r, number(toks.get(2), key, 0, max), number(toks.get(3), key, 0, max));
        }

        /**
         * A map statement: options, then the file name (the rest of the line), loaded as an image
         * texture through the cache.
         */
        private MapSpec map(List<Tok> toks, boolean bump) {
            String key = toks.get(0).text();
            double su = 1, sv = 1, ou = 0, ov = 0, bm = 1;
            Wrap wrap = Wrap.REPEAT;
            int i = 1;
            while (i < toks.size() && toks.get(i).text().startsWith("-") && !isNumber(toks.get(i).text())) {
                Tok opt = toks.get(i++);
                String o = opt.text().toLowerCase(Locale.ROOT);
                switch (o) {
                    case "-o", "-s" -> {
                        double[] v = new double[3];
                        int k = 0;
                        while (k < 3 && i < toks.size() && isNumber(toks.get(i).text())) {
                            v[k++] = number(toks.get(i++), key + " " + opt.text(), -Ranges.MAX_NUMBER, Ranges.MAX_NUMBER);
                        }
                        if (k == 0) throw error(i < toks.size() ? toks.get(i).column() : current.length() + 1, "expected 1 to 3 numbers (u, v, w) after '" + opt.text() + "'");
                        double u = v[0], vv = k > 1 ? v[1] : o.equals("-s") ? u : 0;
                        if (o.equals("-o")) {
                            ou = u;
                            ov = vv;
                        } else {
                            if (!(u > 0) || !(vv > 0)) throw error(opt.column(), "'-s' scales must be above 0, found " + u + " " + vv);
                            su = u;
                            sv = vv;
                        }
                    }
                    case "-clamp" -> {
                        Tok v = value(toks, i++, "on or off after '-clamp'");
                        String w = v.text().toLowerCase(Locale.ROOT);
                        if (!w.equals("on") && !w.equals("off")) throw error(v.column(), "expected on or off after '-clamp', found " + MessageText.quote(v.text()));
                        wrap = w.equals("on") ? Wrap.CLAMP : Wrap.REPEAT;
                    }
                    case "-bm" -> {
                        if (!bump) throw error(opt.column(), "'-bm' (the bump multiplier) applies to map_Bump and bump only");
                        bm = number(value(toks, i++, "a number after '-bm'"), "-bm", -Ranges.MAX_NUMBER, Ranges.MAX_NUMBER);
                    }
                    default -> throw error(opt.column(), "texture option " + MessageText.quote(opt.text()) + " is not supported"
                            + SceneGrammar.didYouMean(o, bump ? OPTIONS : OPTIONS.subList(0, 3)) + " (supported: -o, -s, -clamp" + (bump ? ", -bm" : "") + ")");
                }
            }
            if (i >= toks.size()) throw error(current.length() + 1, "expected a texture file name for '" + key + "', found end of line");
            Tok nameTok = toks.get(i);
            String name = rest(nameTok);
            Path path;
            try {
                path = (folder == null ? Path.of(name) : folder.resolve(name)).normalize();
            } catch (InvalidPathException e) {
                throw error(nameTok.column(), "texture file name " + MessageText.quote(name) + " is not a valid path: " + e.getReason());
            }
            String refusal = gate.refusal(path);
            if (refusal != null) throw error(nameTok.column(), "texture image " + MessageText.quote(name) + " " + refusal);
            gate.record(path, "texture image", SceneException.location(file, line, nameTok.column()));
            String problem = InputFiles.problem(path);
            if (problem != null) {
                throw error(nameTok.column(), "texture image " + MessageText.quote(name) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
            }
            ImageTexture texture;
            try {
                texture = new ImageTexture(textures.load(path), Filter.BILINEAR, wrap);
            } catch (IOException e) {
                String reason = String.valueOf(e.getMessage());
                if (reason.startsWith(path + ": ")) reason = reason.substring(path.toString().length() + 2);
                throw error(nameTok.column(), "cannot read texture image " + MessageText.quote(name) + ": " + reason);
            }
            // -s multiplies the coordinates: the mapping's scale is the repeat's length, 1/s.
            return new MapSpec(texture, new Uv(1 / su, 1 / sv, ou, ov), bm);
        }

        private static boolean isNumber(String s) {
            if (s.isEmpty()) return false;
            char c = s.charAt(0);
            if (!(c == '-' || c == '+' || c == '.' || c >= '0' && c <= '9')) return false;
            try {
                Double.parseDouble(s);
                return !s.endsWith("d") && !s.endsWith("D") && !s.endsWith("f") && !s.endsWith("F");
            } catch (NumberFormatException e) {
                return false;
            }
        }

        /** The number of a token, lo..hi; an error naming the key otherwise. */
        private double number(Tok t, String key, double lo, double hi) {
            if (!isNumber(t.text())) throw error(t.column(), "expected a number for '" + key + "', found " + MessageText.quote(t.text()));
            double v = Double.parseDouble(t.text());
            if (!(v >= lo && v <= hi)) {
                throw error(t.column(), "'" + key + "' must be between " + Ranges.show(lo) + " and " + Ranges.show(hi) + ", found " + MessageText.quote(t.text(), ""));
            }
            return v;
        }

        /** Token {@code i}, or an error "expected {what}, found end of line". */
        private Tok value(List<Tok> toks, int i, String what) {
            if (i < toks.size()) return toks.get(i);
            throw error(current.length() + 1, "expected " + what + ", found end of line");
        }

        /** Nothing after token {@code i - 1}. */
        private void end(List<Tok> toks, int i, String after) {
            if (i < toks.size()) throw error(toks.get(i).column(), "unexpected " + MessageText.quote(toks.get(i).text()) + " after " + after);
        }

        /** The rest of the line from token {@code t}, trailing blanks dropped. */
        private String rest(Tok t) {
            return current.substring(t.index()).strip();
        }

        /**
         * The first {@link #MAX_TOKENS} tokens of a line: no statement has more (a map's file name
         * is the rest of the line), and a line of millions of numbers must not become as many
         * objects (a statement with too many values is refused at its first extra one, among them).
         */
        private List<Tok> tokens(String s) {
            List<Tok> out = new ArrayList<>();
            int i = 0, n = s.length(), column = 1;
            while (i < n && out.size() < MAX_TOKENS) {
                char c = s.charAt(i);
                if (c == ' ' || c == '\t' || c == '\f' || c == 0x0B) {
                    i++;
                    column++;
                    continue;
                }
                int start = i, startColumn = column;
                while (i < n && " \t\f\u000B".indexOf(s.charAt(i)) < 0) {
                    if (!Character.isLowSurrogate(s.charAt(i))) column++;
                    i++;
                }
                out.add(new Tok(s.substring(start, i), start, startColumn));
            }
            return out;
        }

        private SceneException error(int column, String message) {
            return new SceneException(file, line, column, message);
        }
    }
}
