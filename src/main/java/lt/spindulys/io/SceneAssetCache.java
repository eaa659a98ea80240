package lt.spindulys.io;

import java.io.IOException;
import java.nio.file.InvalidPathException;
import java.nio.file.Path;
import java.util.HashMap;
import java.util.LinkedHashMap;
import java.util.List;
import java.util.Map;

import lt.spindulys.io.SceneBlockReader.GroupMaterial;
import lt.spindulys.io.SceneBlockReader.Prop;
import lt.spindulys.io.SceneBlockReader.Props;
import lt.spindulys.io.SceneLexer.Token;
import lt.spindulys.limits.InputFiles;
import lt.spindulys.limits.MessageText;
import lt.spindulys.material.Material;
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
    /** Where every file named passes before it is opened: refused outside the asset folders, recorded as read. */
    private final AssetGate gate;
    /** The scene file as messages name it, for the places recorded. */
    private final String file;
    /** Every image of this parse, loaded once however many textures name it. */
    private final TextureCache textureCache = new TextureCache();
    /** The first mesh read from each file; later statements naming the file get instances of it. */
    private final Map<Path, TriangleMesh> meshes = new HashMap<>();
    /** Likewise for subdivision surfaces, by everything that decides the refined surface. */
    private final Map<SubdivKey, SubdivisionSurface> surfaces = new HashMap<>();
    /** Adaptive surfaces by control mesh and scheme (level -1): later statements share the first one's refiner. */
    private final Map<SubdivKey, AdaptiveSubdivisionSurface> adaptiveSurfaces = new HashMap<>();
    /** The first subdiv block's 'method' key that chose an adaptive method, or null: such a surface needs a perspective view. */
    private Prop firstAdaptiveMethod;
    /** What each OBJ file read says about materials (not the mesh, which is not kept here). */
    private final Map<Path, MaterialRefs> objMaterials = new HashMap<>();

    /** An OBJ file's mtllib file names and each face group's first usemtl, in group order. */
    private record MaterialRefs(List<ObjReader.Ref> libraries, List<ObjReader.Ref> groups) {
        static MaterialRefs of(ObjReader.Read r) { return new MaterialRefs(r.libraries(), r.groups()); }
    }
    /** Each OBJ file's libraries' materials by name, read when a statement first needs them. */
    private final Map<Path, Map<String, Material>> objLibraries = new HashMap<>();
    /** Every material library of this parse, read once however many OBJ files name it. */
    private final Map<Path, Map<String, Material>> libraries = new HashMap<>();

    /**
     * @param baseDir the absolute folder against which relative file names are resolved
     * @param gate    what the parse may read, and the record of what it read
     * @param file    the scene file as messages name it
     */
    SceneAssetCache(SceneErrors err, Path baseDir, AssetGate gate, String file) {
        this.err = err;
        this.baseDir = baseDir;
        this.gate = gate;
        this.file = file;
    }

    /**
     * Refuses a file outside the asset folders, before anything opens it, at the key's value; else
     * records it as read, with that place.
     */
    private void admit(Prop f, String what, String rel, Path path) {
        String refusal = gate.refusal(path);
        if (refusal != null) throw err.error(f.valueAt(), what + " " + MessageText.quote(rel) + " " + refusal);
        gate.record(path, what, SceneException.location(file, f.valueAt().line(), f.valueAt().column()));
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
        admit(f, "mesh file", rel, path);
        // Checked here rather than left to the reader so the message points into the scene file.
        String problem = InputFiles.problem(path);
        if (problem != null) throw err.error(f.valueAt(), "mesh file " + MessageText.quote(rel) + " " + problem + " (looked in " + MessageText.cut(path.toString(), 200) + ")");
        TriangleMesh first = meshes.get(path);
        if (first != null) {
            // The same file again: another placement of the same geometry, read and indexed once.
            TriangleMesh m = first.instance();
            Object shading = p.get("shading");
            m.smooth(shading != null ? "smooth".equals(shading) : first.hasNormals());
            groupMaterials(p, path, m.groupNames(), m::groupMaterial);
            return m;
        }
        MeshData data;
        try {
            ObjReader.Read read = ObjReader.readMesh(path);
            objMaterials.put(path, MaterialRefs.of(read));
            data = read.mesh();
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
        groupMaterials(p, path, m.groupNames(), m::groupMaterial);
        return m;
    }

    /** How an object takes a face group's material (its {@code groupMaterial}). */
    @FunctionalInterface
    private interface GroupSetter {
        void set(String group, Material m);
    }

    /**
     * Gives every face group of an object made from the OBJ file at {@code obj} its material: the
     * block's 'usemtl' for that name, else the file's material libraries'. A block with its own
     * 'material' overrides every group, so nothing is resolved then. A 'usemtl' naming no group of
     * the file is an error at its name; a group that neither gives a material is an error at the
     * file's first 'usemtl' of it.
     */
    private void groupMaterials(Props p, Path obj, String[] groups, GroupSetter setter) {
        Map<String, GroupMaterial> overrides = new LinkedHashMap<>();
        for (Prop pr : p.all) {
            if (!pr.key().name().equals("usemtl")) continue;
            GroupMaterial g = (GroupMaterial) pr.value();
            GroupMaterial earlier = overrides.putIfAbsent(g.group(), g);
            if (earlier != null) {
                throw err.error(g.at(), "usemtl " + MessageText.quote(g.group()) + " given twice (first at " + earlier.at().position() + ")");
            }
            boolean known = false;
            if (groups != null) for (String n : groups) known |= n.equals(g.group());
            if (!known) {
                String file = (String) p.prop("file").value();
                throw err.error(g.at(), "usemtl " + MessageText.quote(g.group()) + ": " + MessageText.quote(file)
                        + (groups == null || groups.length == 0 ? " has no usemtl statements" : " has no usemtl of that name"
                        + SceneGrammar.didYouMean(g.group(), List.of(groups)) + " (its names: " + MessageText.cut(String.join(", ", groups), 200) + ")"));
            }
        }
        if (groups == null || p.prop("material") != null) return;
        MaterialRefs read = objMaterials.get(obj);
        Map<String, Material> fromFiles = null;
        for (int g = 0; g < groups.length; g++) {
            String name = groups[g];
            GroupMaterial o = overrides.get(name);
            Material m;
            if (o != null) {
                m = o.material();
            } else {
                if (fromFiles == null) fromFiles = libraryMaterials(obj, read);
                m = fromFiles.get(name);
                if (m == null) {
                    ObjReader.Ref at = read.groups().get(g);
                    String libs = read.libraries().isEmpty() ? "the file names no material library (mtllib)"
                            : "no material library it names (" + MessageText.cut(String.join(", ", read.libraries().stream().map(ObjReader.Ref::name).toList()), 200)
                            + ") defines it" + SceneGrammar.didYouMean(name, fromFiles.keySet());
                    throw new SceneException(obj.toString(), at.line(), at.column(), "no material " + MessageText.quote(name) + ": " + libs
                            + ", and the scene gives none (write usemtl \"" + MessageText.cut(name, 40) + "\" and a material in the '"
                            + p.block.keyword() + "' block at " + p.opener.position() + ")");
                }
            }
            setter.set(name, m);
        }
    }

    /**
     * The materials of the libraries an OBJ file names, by name (read once per library file and
     * once per OBJ file); a library that is missing is an error at its mtllib, and a name that two
     * of them define an error at the second's.
     */
    private Map<String, Material> libraryMaterials(Path obj, MaterialRefs read) {
        Map<String, Material> all = objLibraries.get(obj);
        if (all != null) return all;
        all = new HashMap<>();
        Map<String, String> definedIn = new HashMap<>();
        Path folder = obj.toAbsolutePath().getParent();
        for (ObjReader.Ref lib : read.libraries()) {
            Path path;
            try {
                path = (folder == null ? Path.of(lib.name()) : folder.resolve(lib.name())).normalize();
            } catch (InvalidPathException e) {
                throw new SceneException(obj.toString(), lib.line(), lib.column(), "material library name " + MessageText.quote(lib.name()) + " is not a valid path: " + e.getReason());
            }
            String refusal = gate.refusal(path);
            if (refusal != null) {
                throw new SceneException(obj.toString(), lib.line(), lib.column(), "material library " + MessageText.quote(lib.name()) + " " + refusal);
            }
            String problem = InputFiles.problem(path);
            if (problem != null) {
                throw new SceneException(obj.toString(), lib.line(), lib.column(), "material library " + MessageText.quote(lib.name()) + " " + problem
                        + " (looked in " + MessageText.cut(path.toString(), 200) + "; a 'material' key on the object replaces the file's materials)");
            }
            Map<String, Material> one = libraries.get(path);
            if (one == null) {
                gate.record(path, "material library", SceneException.location(obj.toString(), lib.line(), lib.column()));
                one = MtlReader.read(path, textureCache, gate);
                libraries.put(path, one);
            }
            for (Map.Entry<String, Material> e : one.entrySet()) {
                String before = definedIn.putIfAbsent(e.getKey(), lib.name());
                if (before != null && !before.equals(lib.name())) {
                    throw new SceneException(obj.toString(), lib.line(), lib.column(), "material " + MessageText.quote(e.getKey()) + " is defined both in "
                            + MessageText.quote(before) + " and in " + MessageText.quote(lib.name()) + " (each name once)");
                }
                all.putIfAbsent(e.getKey(), e.getValue());
            }
        }
        objLibraries.put(obj, all);
        return all;
    }

    /** {@return the first subdiv block's 'method' key that chose an adaptive method, or null if none did} */
    Prop firstAdaptiveMethod() { return firstAdaptiveMethod; }

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
        if (!method.equals("uniform") && firstAdaptiveMethod == null) firstAdaptiveMethod = p.prop("method");
        if (method.equals("uniform")) {
            for (Prop adaptiveOnly : new Prop[] {target, levels, maxLevel}) {
                if (adaptiveOnly != null) {
                    throw err.error(adaptiveOnly.at(), "'" + adaptiveOnly.key().name() + "' needs an adaptive method (method projected, lazy or combined)");
                }
            }
        } else if (levelProp != null && target != null) {
            // 'levels' may stay with a fixed level: it picks the tessellation (rate: grids on the limit surface; edge or
            // object: the power-of-two refinement), but a target would be ignored.
            throw err.error(target.at(), "'target' chooses levels from the view, but 'level' fixes one; give one of them");
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
            if (same != null) {
                // The same surface again: refined once, placed twice.
                SubdivisionSurface s = same.instance();
                groupMaterials(p, path, s.groupNames(), s::groupMaterial);
                return s;
            }
            SubdivInput input = readSurface(p, f, rel, path);
            boolean limit = positions == SubdivisionSurface.Positions.LIMIT;
            try {
                SubdivisionSurface.checkLevel(level, input.refinedFaceCount(level),
                        SubdivisionSurface.bytesPerFace(input.options().scheme(), limit));
            } catch (IllegalArgumentException e) {
                if (!(e instanceof InsufficientMemoryException) && input.refinedFaceCount(level) <= SubdivisionSurface.MAX_FACES) throw err.wrap(levelAt, e);
                // Too large to refine whole: the combined method gives the same triangles within the budget, with the
                // refined positions by the power-of-two levels, with the limit positions by the rates (2^level on every edge).
                try {
                    GObject o = adaptive(p, f, key, input, AdaptiveSubdivisionSurface.Method.COMBINED, level, null, null, null, smooth);
                    ((AdaptiveSubdivisionSurface) o).levels(limit ? AdaptiveSubdivisionSurface.Levels.RATE : AdaptiveSubdivisionSurface.Levels.EDGE);
                    return o;
                } catch (SceneException a) {
                    // A mesh the adaptive methods refuse: the level is refused for what the user asked.
                    if (!(a.getCause() instanceof IllegalArgumentException why)) throw a;
                    throw err.error(levelAt, e.getMessage() + "; nor can the combined method, which renders such levels otherwise: " + why.getMessage());
                }
            }
            try {
                SubdivisionSurface made = new SubdivisionSurface(input.toControlMesh(), level, smooth, positions);
                surfaces.put(key, made);
                groupMaterials(p, path, made.groupNames(), made::groupMaterial);
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
        if (levels != null) {
            s.levels(switch ((String) levels.value()) {
                case "object" -> AdaptiveSubdivisionSurface.Levels.OBJECT;
                case "edge" -> AdaptiveSubdivisionSurface.Levels.EDGE;
                default -> AdaptiveSubdivisionSurface.Levels.RATE;
            });
        }
        if (maxLevel != null) {
            int max = (Integer) maxLevel.value();
            if (max < 0 || max > SubdivisionSurface.MAX_LEVEL) {
                throw err.error(maxLevel.at(), "maxlevel must be between 0 and " + SubdivisionSurface.MAX_LEVEL + ", found " + max);
            }
            s.maxLevel(max);
        }
        groupMaterials(p, key.file(), s.groupNames(), s::groupMaterial);
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
            if (ext.equals("obj")) {
                ObjReader.Read read = ObjReader.readSubdivision(path);
                objMaterials.put(path, MaterialRefs.of(read));
                input = read.subdiv();
            } else {
                input = SubdivInput.of(WorkframeReader.readMesh(path));
            }
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
        admit(f, what, rel, path);
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
