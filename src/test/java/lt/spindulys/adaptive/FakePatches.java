package lt.spindulys.adaptive;

import java.util.concurrent.atomic.AtomicIntegerArray;

/** A fake tessellation for the cache tests: patches with a deterministic payload and size, and a build count per face. */
final class FakePatches implements PatchSource {

    /** A patch that is a pure function of its face; equal patches are equal objects. */
    record Patch(int face, long payload, long bytes) implements CachedPatch {}

    final int faces;
    private final long baseBytes;
    private final long varyBytes;
    final AtomicIntegerArray builds;

    /** Patches of {@code baseBytes} plus up to {@code varyBytes - 1} more, varying with the face. */
    FakePatches(int faces, long baseBytes, long varyBytes) {
        this.faces = faces;
        this.baseBytes = baseBytes;
        this.varyBytes = varyBytes;
        this.builds = new AtomicIntegerArray(faces);
    }

    static long payload(int face) {
        long z = face * 0x9E3779B97F4A7C15L + 0x632BE59BD9B4E019L;
        z = (z ^ (z >>> 30)) * 0xBF58476D1CE4E5B9L;
        z = (z ^ (z >>> 27)) * 0x94D049BB133111EBL;
        return z ^ (z >>> 31);
    }

    long bytesOf(int face) {
        return baseBytes + (varyBytes <= 1 ? 0 : Math.floorMod(payload(face), varyBytes));
    }

    Patch expected(int face) {
        return new Patch(face, payload(face), bytesOf(face));
    }

    @Override
    public CachedPatch build(int face) {
        builds.incrementAndGet(face);
        return expected(face);
    }

    long totalBuilds() {
        long n = 0;
        for (int i = 0; i < faces; i++) n += builds.get(i);
        return n;
    }
}
