package lt.spindulys.io;

import java.nio.file.Path;

import lt.spindulys.scene.MeshData;

/** Reads Wavefront OBJ meshes (v, vn, vt, f with polygons and negative indices). */
public final class ObjReader {
    private ObjReader() {}

    /** Reads the file; malformed input throws {@link SceneException} naming file:line:column. */
    public static MeshData read(Path file) throws java.io.IOException {
        throw new UnsupportedOperationException("TODO");
    }
}
