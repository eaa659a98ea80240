package lt.spindulys.io;

import java.util.Arrays;

/**
 * Growable primitive arrays as a list of blocks: one allocation per block, none per element,
 * and nothing is copied until the exact-size array is made (a doubling array copies each
 * element about twice more, and the garbage it leaves is as large as the mesh).
 */
abstract class BlockList<A> {
    /** First block of a growable array; blocks double up to {@link #MAX_BLOCK} elements. */
    private static final int FIRST_BLOCK = 1024, MAX_BLOCK = 1 << 16;

    /** The filled blocks (primitive arrays), in order. */
    private Object[] blocks = new Object[8];
    private int full, before;

    /** A new block of the given length. */
    abstract A block(int length);

    /** Keeps the filled block and returns the next, empty one. */
    final A next(A filled, int length) {
        if (full == blocks.length) blocks = Arrays.copyOf(blocks, 2 * full);
        blocks[full++] = filled;
        before += length;
        return block(Math.min(MAX_BLOCK, 2 * length));
    }

    /** Elements added: those of the filled blocks and {@code n} of the current one. */
    final int size(int n) { return before + n; }

    /** Copies the elements into {@code to} from {@code at}: the filled blocks, then n of {@code cur}. */
    final void copyTo(A cur, int n, A to, int at) {
        for (int i = 0; i < full; i++) {
            int len = java.lang.reflect.Array.getLength(blocks[i]);
            System.arraycopy(blocks[i], 0, to, at, len);
            at += len;
        }
        System.arraycopy(cur, 0, to, at, n);
    }

    /** A growable array of doubles (see {@link BlockList}). */
    static final class Doubles extends BlockList<double[]> {
        private double[] cur = new double[FIRST_BLOCK];
        private int n;

        @Override double[] block(int length) { return new double[length]; }

        void add(double v) {
            if (n == cur.length) {
                cur = next(cur, cur.length);
                n = 0;
            }
            cur[n++] = v;
        }

        int size() { return size(n); }

        void copyTo(double[] to, int at) { copyTo(cur, n, to, at); }

        double[] toArray() {
            double[] a = new double[size()];
            copyTo(a, 0);
            return a;
        }
    }

    /** A growable array of ints (see {@link BlockList}). */
    static final class Ints extends BlockList<int[]> {
        private int[] cur = new int[FIRST_BLOCK];
        private int n;

        @Override int[] block(int length) { return new int[length]; }

        void add(int v) {
            if (n == cur.length) {
                cur = next(cur, cur.length);
                n = 0;
            }
            cur[n++] = v;
        }

        int size() { return size(n); }

        void copyTo(int[] to, int at) { copyTo(cur, n, to, at); }

        int[] toArray() {
            int[] a = new int[size()];
            copyTo(a, 0);
            return a;
        }
    }
}
