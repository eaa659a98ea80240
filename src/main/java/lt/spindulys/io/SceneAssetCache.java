package lt.spindulys.io;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.Map;

import lt.spindulys.io.SceneBlockReader.Prop;
import lt.spindulys.io.SceneBlockReader.Props;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.MessageText;
import lt.spindulys.mesh.MeshData;
import lt.spindulys.scene.AdaptiveSubdivisionSurface;
import lt.spindulys.scene.GObject;
import lt.spindulys.scene.SubdivisionSurface;
import lt.spindulys.limits.InsufficientMemoryException;
import lt.spindulys.scene.TriangleMesh;
import lt.spindulys.subdiv.ControlMesh;
import lt.spindulys.subdiv.SubdivInput;
import lt.spindulys.subdiv.SubdivOptions;
import lt.spindulys.texture.TextureCache;
import lt.spindulys.texture.TextureImage;

/**
 * The files one scene file names (meshes, subdivision control meshes with their unwraps, texture
 * images), resolved against the scene's folder and each read once per parse: a later statement
 * naming the same mesh, or the same surface, gets an instance of the first (one copy of the
 * geometry, placed again), and an image named by several textures is decoded once. Errors name
 * the file as the scene wrote it, at its value.
 */
final class SceneAssetCache {
    private final SceneErrors err;
    private final Path baseDir;
    /** Every image of this parse, loaded once however many textures name it. */
    private final TextureCache textureCache = new TextureCache();
    /** The first mesh read from each file; later statements naming the file get instances of it. */
    private final Map<Path, TriangleMesh> meshes = new HashMap<>();
    /** Likewise for subdivision surfaces, by everything that decides the refined surface. */
    private final Map<SubdivKey, SubdivisionSurface> surfaces = new HashMap<>();
    /** Adaptive surfaces by control mesh and scheme (level -1): later statements share the first one's refiner. */
    private final Map<SubdivKey, AdaptiveSubdivisionSurface> adaptiveSurfaces = new HashMap<>();

    /** @param baseDir the absolute folder against which relative file names are resolved */
    SceneAssetCache(SceneErrors err, Path baseDir) {
        this.err = err;
        this.baseDir = baseDir;
    }

    /**
     * The image a texture block's 'image' key names, decoded once however many textures name it;
     * an error at the value if it cannot be read.
     */
    TextureImage image(Prop image) {
        return image(image, "texture image");
    }

    /** Likewise, for an image that {@code what} names in messages ("texture image", "environment image"). */
    TextureImage image(Prop image, String what) {
        Path path = existingFile(image, what);
        TextureImage img;
        try {
            img = textureCache.load(path);
        } catch (IOException e) {
            // The cache says "FILE: reason"; the scene location and the name as written replace FILE.
            String reason = String.valueOf(e.getMessage());
            if (reason.startsWith(path + ": ")) reason = reason.substring(path.toString().length() + 2);
            throw err.error(image.valueAt(), "cannot read " + what + " " + MessageText.quote((String) image.value()) + ": " + reason);
        }
        return img;
    }

    /** A mesh block's triangle mesh: its file read and indexed on first use, an instance of that mesh after. */
    TriangleMesh mesh(Props p) {
        Prop f = p.prop("file");
        String rel = (String) f.value();
        Path path;
        try {
            path = baseDir.resolve(rel).normalize();
        } catch (InvalidPathException e) {
            throw err.error(f.valueAt(), "mesh file name " + MessageText.quote(rel) + " is not a valid path: " + e.getReason());
        }
        // Checked here rather than left to the reader so the message points into the scene file.
        String problem = InputFiles.problem(path);
        if (problem != null) throw err.error(f.valueAt(), "mesh file " + MessageText.quote(rel) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
        TriangleMesh first = meshes.get(path);
        if (first != null) {
            // The same file again: another placement of the same geometry, read and indexed once.
            TriangleMesh m = first.instance();
            Object shading = p.get("shading");
            m.smooth(shading != null ? "smooth".equals(shading) : first.hasNormals());
            return m;
        }
        MeshData data;
        try {
            data = ObjReader.read(path);
        } catch (IOException e) {
            throw err.error(f.valueAt(), "cannot read mesh file " + MessageText.quote(rel) + ": " + e.getMessage());
        }
        TriangleMesh m;
        try {
            m = new TriangleMesh(data);
        } catch (IllegalArgumentException e) {
            throw err.wrap(f.valueAt(), e);
        }
        Object shading = p.get("shading");
        m.smooth(shading != null ? "smooth".equals(shading) : data.normals() != null);
        meshes.put(path, m);
        return m;
    }

    /**
     * A subdivision surface: the control mesh from an OBJ (with its tags) or a Workframe .dat
     * file, an optional .tex unwrap as its UVs, the block's scheme keys (the scheme itself among
     * them) over the file's options,
     * refined uniformly ({@code method uniform}, the default) or adaptively. A uniform level whose
     * refinement would not fit in the heap is not refused: the combined method renders it at the
     * same level within the scene's memory budget.
     */
    GObject surface(Props p) {
        Prop levelProp = p.prop("level");
        int level = (Integer) p.get("level");
        Token levelAt = levelProp != null ? levelProp.at() : p.opener;
        try {
            SubdivisionSurface.checkLevel(level);
        } catch (IllegalArgumentException e) {
            throw err.wrap(levelAt, e);
        }
        String method = (String) p.get("method");
        Prop target = p.prop("target"), levels = p.prop("levels"), maxLevel = p.prop("maxlevel"), positionsProp = p.prop("positions");
        SubdivisionSurface.Positions positions = "limit".equals(p.get("positions")) ? SubdivisionSurface.Positions.LIMIT : SubdivisionSurface.Positions.REFINED;
        if (positionsProp != null && !method.equals("uniform")) {
            throw err.error(positionsProp.at(), "'positions' needs method uniform: the adaptive methods (projected, lazy, combined) place the vertices"
                    + " where the refinement puts them");
        }
        if (method.equals("uniform")) {
            for (Prop adaptiveOnly : new Prop[] {target, levels, maxLevel}) {
                if (adaptiveOnly != null) {
                    throw err.error(adaptiveOnly.at(), "'" + adaptiveOnly.key().name() + "' needs an adaptive method (method projected, lazy or combined)");
                }
            }
        } else if (levelProp != null && (target != null || levels != null)) {
            Prop other = target != null ? target : levels;
            throw err.error(other.at(), "'" + other.key().name() + "' chooses levels from the view, but 'level' fixes one; give one of them");
        }
        Prop f = p.prop("file");
        String rel = (String) f.value();
        Path path = existingFile(f, "subdivision mesh file");
        Prop uvProp = p.prop("uv");
        boolean smooth = "smooth".equals(p.get("shading"));
        SubdivKey key = new SubdivKey(path, uvProp != null ? existingFile(uvProp, "unwrap file") : null, level,
                smooth, positions, (String) p.get("scheme"), (String) p.get("boundary"), (String) p.get("uvinterpolation"),
                (String) p.get("creasing"), (String) p.get("triangles"));
        if (method.equals("uniform")) {
            SubdivisionSurface same = surfaces.get(key);
            if (same != null) return same.instance(); // the same surface again: refined once, placed twice
            SubdivInput input = readSurface(p, f, rel, path);
            boolean limit = positions == SubdivisionSurface.Positions.LIMIT;
            try {
                SubdivisionSurface.checkLevel(level, input.refinedFaceCount(level),
                        SubdivisionSurface.bytesPerFace(input.options().scheme(), limit));
            } catch (IllegalArgumentException e) {
                if (!(e instanceof InsufficientMemoryException) && input.refinedFaceCount(level) <= SubdivisionSurface.MAX_FACES) throw err.wrap(levelAt, e);
                // The combined method has no limit positions: the level is refused rather than rendered otherwise.
                if (limit) throw err.error(levelAt, e.getMessage() + "; positions limit needs uniform refinement (the adaptive methods, which render such levels otherwise, have no limit positions)");
                // Too large to refine whole: the combined method gives the same triangles within the budget.
                return adaptive(p, f, key, input, AdaptiveSubdivisionSurface.Method.COMBINED, level, null, null, null, smooth);
            }
            try {
                SubdivisionSurface made = new SubdivisionSurface(input.toControlMesh(), level, smooth, positions);
                surfaces.put(key, made);
                return made;
            } catch (IllegalArgumentException e) {
                throw err.wrap(f.valueAt(), e);
            }
        }
        AdaptiveSubdivisionSurface.Method m = switch (method) {
            case "projected" -> AdaptiveSubdivisionSurface.Method.PROJECTED;
            case "lazy" -> AdaptiveSubdivisionSurface.Method.LAZY;
            case "combined" -> AdaptiveSubdivisionSurface.Method.COMBINED;
            default -> throw new IllegalStateException("method choice without a mapping: " + method);
        };
        return adaptive(p, f, key, null, m, levelProp != null ? level : -1, target, levels, maxLevel, smooth);
    }

    /** An adaptive surface; statements naming the same control mesh and scheme share its refiner. */
    private GObject adaptive(Props p, Prop f, SubdivKey key, SubdivInput read, AdaptiveSubdivisionSurface.Method method, int level,
                             Prop target, Prop levels, Prop maxLevel, boolean smooth) {
        SubdivKey shared = new SubdivKey(key.file(), key.uv(), -1, key.smooth(), key.positions(), key.scheme(), key.boundary(), key.uvinterpolation(),
                key.creasing(), key.triangles());
        AdaptiveSubdivisionSurface first = adaptiveSurfaces.get(shared);
        AdaptiveSubdivisionSurface s;
        if (first != null) {
            s = first.sibling(method);
        } else {
            SubdivInput input = read != null ? read : readSurface(p, f, (String) f.value(), key.file());
            try {
                s = new AdaptiveSubdivisionSurface(input.toControlMesh(), method, smooth);
            } catch (IllegalArgumentException e) {
                throw err.wrap(f.valueAt(), e);
            }
            adaptiveSurfaces.put(shared, s);
        }
        s.level(level);
        try {
            if (target != null) s.target((Double) target.value());
        } catch (IllegalArgumentException e) {
            throw err.wrap(target.at(), e);
        }
        if (levels != null) s.levels("object".equals(levels.value()) ? AdaptiveSubdivisionSurface.Levels.OBJECT : AdaptiveSubdivisionSurface.Levels.EDGE);
        if (maxLevel != null) {
            int max = (Integer) maxLevel.value();
            if (max < 0 || max > SubdivisionSurface.MAX_LEVEL) {
                throw err.error(maxLevel.at(), "maxlevel must be between 0 and " + SubdivisionSurface.MAX_LEVEL + ", found " + max);
            }
            s.maxLevel(max);
        }
        return s;
    }

    /** What makes two subdiv statements the same surface: file, unwrap, level, shading, vertex positions and scheme words. */
    private record SubdivKey(Path file, Path uv, int level, boolean smooth, SubdivisionSurface.Positions positions, String scheme, String boundary,
                             String uvinterpolation, String creasing, String triangles) {}

    /** The control mesh of a subdiv block, with its unwrap and the block's scheme keys. */
    private SubdivInput readSurface(Props p, Prop f, String rel, Path path) {
        String ext = extension(rel);
        if (!ext.equals("obj") && !ext.equals("dat")) {
            throw err.error(f.valueAt(), "subdivision mesh file " + MessageText.quote(rel) + " must be a Wavefront .obj or a Workframe .dat file");
        }
        SubdivInput input;
        try {
            input = ext.equals("obj") ? ObjReader.readSubdiv(path) : SubdivInput.of(WorkframeReader.readMesh(path));
        } catch (IOException e) {
            throw err.error(f.valueAt(), "cannot read subdivision mesh file " + MessageText.quote(rel) + ": " + e.getMessage());
        }
        Prop uv = p.prop("uv");
        if (uv != null) {
            Path uvPath = existingFile(uv, "unwrap file");
            try {
                input = WorkframeReader.readTex(uvPath, input.mesh()).applyTo(input);
            } catch (IOException e) {
                throw err.error(uv.valueAt(), "cannot read unwrap file " + MessageText.quote((String) uv.value()) + ": " + e.getMessage());
            }
        }
        return input.withOptions(options(p, input.options()));
    }

    /** The file's options with the block's scheme keys, where given, in their place. */
    private static SubdivOptions options(Props p, SubdivOptions o) {
        return subdivOptions(o, (String) p.get("scheme"), (String) p.get("boundary"), (String) p.get("uvinterpolation"), (String) p.get("creasing"),
                (String) p.get("triangles"));
    }

    /** {@code base} with each scheme choice of a subdiv block (its grammar word, or null to keep base's) in its place. */
    static SubdivOptions subdivOptions(SubdivOptions base, String scheme, String boundary, String uvinterpolation, String creasing, String triangles) {
        SubdivOptions o = base;
        if (scheme != null) {
            SubdivOptions.Scheme s = SubdivOptions.Scheme.ofKeyword(scheme);
            if (s == null) throw new IllegalStateException("scheme choice without a mapping: " + scheme);
            o = o.withScheme(s);
        }
        if (boundary != null) {
            o = o.withBoundary(switch (boundary) {
                case "edge-only" -> SubdivOptions.Boundary.EDGE_ONLY;
                case "edge-and-corner" -> SubdivOptions.Boundary.EDGE_AND_CORNER;
                case "none" -> SubdivOptions.Boundary.NONE;
                default -> throw new IllegalStateException("boundary choice without a mapping: " + boundary);
            });
        }
        if (uvinterpolation != null) {
            o = o.withFaceVarying(switch (uvinterpolation) {
                case "none" -> SubdivOptions.FaceVarying.NONE;
                case "corners-only" -> SubdivOptions.FaceVarying.CORNERS_ONLY;
                case "corners-plus1" -> SubdivOptions.FaceVarying.CORNERS_PLUS1;
                case "corners-plus2" -> SubdivOptions.FaceVarying.CORNERS_PLUS2;
                case "boundaries" -> SubdivOptions.FaceVarying.BOUNDARIES;
                case "all" -> SubdivOptions.FaceVarying.ALL;
                default -> throw new IllegalStateException("uvinterpolation choice without a mapping: " + uvinterpolation);
            });
        }
        if (creasing != null) {
            o = o.withCreasing(switch (creasing) {
                case "uniform" -> SubdivOptions.Creasing.UNIFORM;
                case "chaikin" -> SubdivOptions.Creasing.CHAIKIN;
                default -> throw new IllegalStateException("creasing choice without a mapping: " + creasing);
            });
        }
        if (triangles != null) {
            o = o.withTriangles(switch (triangles) {
                case "catmark" -> SubdivOptions.Triangles.CATMARK;
                case "smooth" -> SubdivOptions.Triangles.SMOOTH;
                default -> throw new IllegalStateException("triangles choice without a mapping: " + triangles);
            });
        }
        return o;
    }

    /** The file a string key names, resolved against the scene's folder; an error at the value if it does not exist. */
    private Path existingFile(Prop f, String what) {
        String rel = (String) f.value();
        Path path;
        try {
            path = baseDir.resolve(rel).normalize();
        } catch (InvalidPathException e) {
            throw err.error(f.valueAt(), what + " name " + MessageText.quote(rel) + " is not a valid path: " + e.getReason());
        }
        String problem = InputFiles.problem(path);
        if (problem != null) throw err.error(f.valueAt(), what + " " + MessageText.quote(rel) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
        return path;
    }

    /** The lower-case extension of a file name ("" when it has none). */
    private static String extension(String name) {
        String base = name.substring(Math.max(name.lastIndexOf('/'), name.lastIndexOf('\\')) + 1);
        int dot = base.lastIndexOf('.');
        return dot < 0 ? "" : base.substring(dot + 1).toLowerCase(java.util.Locale.ROOT);
    }
}
