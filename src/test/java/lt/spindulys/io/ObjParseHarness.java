package lt.spindulys.io;

import java.nio.file.Path;
import java.util.Locale;

import lt.spindulys.mesh.MeshData;

/**
 * Times reading and parsing one OBJ file, several times in this JVM: the first run is the cold
 * one (a new JVM), later runs are warm. Prints MB/s = file bytes / seconds for the read, the parse
 * and both. A measurement tool for docs/performance.md, not a test:
 * {@code java -cp target/classes:target/test-classes lt.spindulys.io.ObjParseHarness FILE [RUNS [THREADS]]}
 * (THREADS parse threads instead of the reader's own choice; the chunks are the same).
 */
public final class ObjParseHarness {
    private ObjParseHarness() {}

    public static void main(String[] args) throws Exception {
        Path file = Path.of(args[0]);
        int runs = args.length > 1 ? Integer.parseInt(args[1]) : 5;
        int threads = args.length > 2 ? Integer.parseInt(args[2]) : 0;
        long check = 0;
        for (int r = 1; r <= runs; r++) {
            long t0 = System.nanoTime();
            byte[] bytes = ObjReader.readBytes(file);
            long t1 = System.nanoTime();
            MeshData m = threads == 0 ? ObjReader.parse(bytes, file.toString())
                    : ObjReader.parse(bytes, file.toString(), (bytes.length + ObjReader.CHUNK_BYTES - 1) / ObjReader.CHUNK_BYTES, threads);
            long t2 = System.nanoTime();
            check += m.vertexIndex().length + m.positions().length;
            double mb = bytes.length / 1e6, read = (t1 - t0) / 1e9, parse = (t2 - t1) / 1e9;
            System.out.printf(Locale.ROOT, "run %d %s: read %.3f s (%.0f MB/s)  parse %.3f s (%.0f MB/s)  total %.3f s (%.0f MB/s)%n",
                    r, r == 1 ? "cold" : "warm", read, mb / read, parse, mb / parse, read + parse, mb / (read + parse));
        }
        System.out.println("(" + check + ")");
    }
}
