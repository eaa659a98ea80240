package lt.spindulys.texture;

import java.io.IOException;
import java.util.Arrays;
import java.util.List;

/**
 * OpenEXR's PIZ codec, decoding side, written from the OpenEXR file-format description and its
 * reference implementation: a block is split into 16-bit words (a HALF sample is one, a FLOAT
 * or UINT sample two, low word first), each channel's words were mapped through a lookup table
 * onto the dense range {@code 0 .. max}, transformed by a 2D Haar-like wavelet and Huffman
 * coded. Decoding reads the bitmap of used values (which gives the table back), the Huffman
 * code table and bits, undoes the wavelet per channel and maps the words back.
 *
 * <p>Every table and buffer is sized once, from the largest block the header declares; each
 * read is checked against the block's end, so corrupt data give an {@link IOException}, never
 * an index error or a loop without end.
 */
final class ExrPiz {
    private static final int BITMAP_SIZE = 8192;
    private static final int USHORT_RANGE = 1 << 16;
    private static final int ENC_SIZE = (1 << 16) + 1;
    private static final int DEC_BITS = 14, DEC_SIZE = 1 << DEC_BITS, DEC_MASK = DEC_SIZE - 1;
    private static final int SHORT_ZEROCODE_RUN = 59, LONG_ZEROCODE_RUN = 63;
    private static final int SHORTEST_LONG_RUN = 2 + LONG_ZEROCODE_RUN - SHORT_ZEROCODE_RUN;

    private final char[] words;
    private final byte[] bitmap = new byte[BITMAP_SIZE];
    private final char[] lut = new char[USHORT_RANGE];
    /** Entries of {@link #lut} the last block set; the rest are 0. */
    private int lutFilled;
    /** Per symbol: code length in the low 6 bits, the code above them. */
    private final long[] hcode = new long[ENC_SIZE];
    /** Per 14-bit prefix: the length and symbol of a short code, or the symbols of the long codes starting with it. */
    private final int[] decLength = new int[DEC_SIZE], decSymbol = new int[DEC_SIZE];
    private final int[][] decLong = new int[DEC_SIZE][];

    // Huffman bit reader state.
    private byte[] in;
    private int inAt, inEnd, outAt;
    private long bits;
    private int bitCount;

    /** A decoder for blocks of at most {@code maxBlockBytes} bytes. */
    ExrPiz(int maxBlockBytes) {
        words = new char[(maxBlockBytes + 1) / 2];
    }

    /** Decodes {@code size} bytes at {@code data[at]} into the {@code rawSize} bytes of a {@code w x h} block. */
    void decode(byte[] data, int at, int size, byte[] raw, int rawSize, List<ExrReader.ExrChannel> channels, int w, int h) throws IOException {
        int end = at + size;
        if (size < 4) throw new IOException("no room for the bitmap bounds");
        int minNonZero = u16(data, at), maxNonZero = u16(data, at + 2);
        at += 4;
        if (maxNonZero >= BITMAP_SIZE) throw new IOException("bitmap end " + maxNonZero + ", expected below " + BITMAP_SIZE);
        Arrays.fill(bitmap, (byte) 0);  // 8 KiB: cheap
        if (minNonZero <= maxNonZero) {
            int n = maxNonZero - minNonZero + 1;
            if (n > end - at) throw new IOException("the bitmap passes the end of the data");
            System.arraycopy(data, at, bitmap, minNonZero, n);
            at += n;
        }
        int maxValue = reverseLut(minNonZero <= maxNonZero ? maxNonZero : -1);
        if (end - at < 4) throw new IOException("no room for the Huffman data length");
        int length = ExrReader.int32(data, at);
        at += 4;
        if (length < 0 || length > end - at) throw new IOException("Huffman data of " + length + " bytes, " + (end - at) + " remain");
        int count = rawSize / 2;
        huffmanDecode(data, at, length, count);

        int start = 0;
        for (ExrReader.ExrChannel c : channels) {
            int wordsPerSample = c.bytes() / 2;
            for (int j = 0; j < wordsPerSample; j++) {
                waveletDecode(start + j, w, wordsPerSample, h, w * wordsPerSample, maxValue);
            }
            start += w * h * wordsPerSample;
        }
        for (int i = 0; i < count; i++) words[i] = lut[words[i]];

        // The words are channel by channel; the block is line by line, each channel's samples in turn.
        int[] channelAt = new int[channels.size()];
        for (int c = 0, s = 0; c < channels.size(); c++) {
            channelAt[c] = s;
            s += w * h * (channels.get(c).bytes() / 2);
        }
        int out = 0;
        for (int y = 0; y < h; y++) {
            for (int c = 0; c < channels.size(); c++) {
                int n = w * (channels.get(c).bytes() / 2);
                for (int k = 0, q = channelAt[c]; k < n; k++, q++) {
                    char v = words[q];
                    raw[out++] = (byte) v;
                    raw[out++] = (byte) (v >> 8);
                }
                channelAt[c] += n;
            }
        }
    }

    private static int u16(byte[] b, int at) {
        return b[at] & 0xFF | (b[at + 1] & 0xFF) << 8;
    }

    /**
     * The table from dense codes back to the values the bitmap marks (0 always); returns the
     * largest code. Only the bitmap's used bytes are scanned and only the entries the previous
     * block filled are cleared, so a file of many small blocks does not pay 65,536 steps for each.
     */
    private int reverseLut(int maxNonZero) {
        int k = 0, end = (maxNonZero + 1) * 8;
        for (int i = 0; i < end; i++) {
            if (i == 0 || (bitmap[i >> 3] & (1 << (i & 7))) != 0) lut[k++] = (char) i;
        }
        if (k == 0) lut[k++] = 0;
        int max = k - 1;
        // Codes above max only occur in corrupt data; they must still map to a value.
        if (lutFilled > k) Arrays.fill(lut, k, lutFilled, (char) 0);
        lutFilled = k;
        return max;
    }

    // ---- Wavelet ----

    /** Undoes the 2D wavelet of one word plane in place: {@code nx x ny} words, {@code ox} apart in x and {@code oy} in y. */
    private void waveletDecode(int base, int nx, int ox, int ny, int oy, int maxValue) {
        boolean w14 = maxValue < (1 << 14);
        int n = Math.min(nx, ny);
        int p = 1;
        while (p <= n) p <<= 1;
        p >>= 1;
        int p2 = p;
        p >>= 1;
        char[] a = words;
        while (p >= 1) {
            int py = base, ey = base + oy * (ny - p2);
            int oy1 = oy * p, oy2 = oy * p2, ox1 = ox * p, ox2 = ox * p2;
            for (; py <= ey; py += oy2) {
                int px = py, ex = py + ox * (nx - p2);
                for (; px <= ex; px += ox2) {
                    int p01 = px + ox1, p10 = px + oy1, p11 = p10 + ox1;
                    int i00, i01, i10, i11;
                    if (w14) {
                        i00 = dec14a(a[px], a[p10]);
                        i10 = dec14b(a[px], a[p10]);
                        i01 = dec14a(a[p01], a[p11]);
                        i11 = dec14b(a[p01], a[p11]);
                        a[px] = (char) dec14a(i00, i01);
                        a[p01] = (char) dec14b(i00, i01);
                        a[p10] = (char) dec14a(i10, i11);
                        a[p11] = (char) dec14b(i10, i11);
                    } else {
                        i00 = dec16a(a[px], a[p10]);
                        i10 = dec16b(a[px], a[p10]);
                        i01 = dec16a(a[p01], a[p11]);
                        i11 = dec16b(a[p01], a[p11]);
                        a[px] = (char) dec16a(i00, i01);
                        a[p01] = (char) dec16b(i00, i01);
                        a[p10] = (char) dec16a(i10, i11);
                        a[p11] = (char) dec16b(i10, i11);
                    }
                }
                if ((nx & p) != 0) {  // the odd column
                    int p10 = px + oy1;
                    int l = a[px], hi = a[p10];
                    a[px] = (char) (w14 ? dec14a(l, hi) : dec16a(l, hi));
                    a[p10] = (char) (w14 ? dec14b(l, hi) : dec16b(l, hi));
                }
            }
            if ((ny & p) != 0) {  // the odd line
                int px = py, ex = py + ox * (nx - p2);
                for (; px <= ex; px += ox2) {
                    int p01 = px + ox1;
                    int l = a[px], hi = a[p01];
                    a[px] = (char) (w14 ? dec14a(l, hi) : dec16a(l, hi));
                    a[p01] = (char) (w14 ? dec14b(l, hi) : dec16b(l, hi));
                }
            }
            p2 = p;
            p >>= 1;
        }
    }

    /** The 14-bit inverse step, on the words as signed shorts: first output. */
    private static int dec14a(int l, int h) {
        int hs = (short) h;
        return ((short) l + (hs & 1) + (hs >> 1)) & 0xFFFF;
    }

    /** The 14-bit inverse step: second output. */
    private static int dec14b(int l, int h) {
        int hs = (short) h;
        return ((short) l + (hs & 1) + (hs >> 1) - hs) & 0xFFFF;
    }

    /** The 16-bit (modular) inverse step: first output. */
    private static int dec16a(int l, int h) {
        int b = (l - (h >> 1)) & 0xFFFF;
        return (h + b - 0x8000) & 0xFFFF;
    }

    /** The 16-bit inverse step: second output. */
    private static int dec16b(int l, int h) {
        return (l - (h >> 1)) & 0xFFFF;
    }

    // ---- Huffman ----

    private void huffmanDecode(byte[] data, int at, int size, int count) throws IOException {
        if (size < 20) {
            if (count != 0) throw new IOException("Huffman data of " + size + " bytes, too short for its 20-byte header");
            return;
        }
        int im = ExrReader.int32(data, at), iM = ExrReader.int32(data, at + 4);
        int nBits = ExrReader.int32(data, at + 12);
        if (im < 0 || im >= ENC_SIZE || iM < 0 || iM >= ENC_SIZE || im > iM) {
            throw new IOException("Huffman symbol range " + im + ".." + iM + ", expected within 0.." + (ENC_SIZE - 1));
        }
        in = data;
        inAt = at + 20;
        inEnd = at + size;
        unpackCodeTable(im, iM);
        if (nBits < 0 || nBits > 8L * (inEnd - inAt)) throw new IOException("Huffman data of " + nBits + " bits, " + (inEnd - inAt) + " bytes remain");
        buildDecodeTable(im, iM);
        decodeSymbols(nBits, iM, count);
    }

    private void needByte() throws IOException {
        if (inAt >= inEnd) throw new IOException("the Huffman data end early");
    }

    private long getBits(int n) throws IOException {
        while (bitCount < n) {
            needByte();
            bits = bits << 8 | (in[inAt++] & 0xFF);
            bitCount += 8;
        }
        bitCount -= n;
        return bits >>> bitCount & ((1L << n) - 1);
    }

    /** The code lengths, run-length packed, then made canonical codes. */
    private void unpackCodeTable(int im, int iM) throws IOException {
        // Only symbols im..iM are ever looked up, so only they are cleared and made canonical.
        int first = im, last = iM;
        Arrays.fill(hcode, first, last + 1, 0);
        bits = 0;
        bitCount = 0;
        for (; im <= iM; im++) {
            int l = (int) getBits(6);
            hcode[im] = l;
            if (l == LONG_ZEROCODE_RUN || l >= SHORT_ZEROCODE_RUN) {
                int run = l == LONG_ZEROCODE_RUN ? (int) getBits(8) + SHORTEST_LONG_RUN : l - SHORT_ZEROCODE_RUN + 2;
                if (im + run > iM + 1) throw new IOException("the Huffman code table runs past its last symbol");
                Arrays.fill(hcode, im, im + run, 0);
                im += run - 1;
            }
        }
        long[] n = new long[59];
        for (int i = first; i <= last; i++) n[(int) hcode[i]]++;
        long c = 0;
        for (int i = 58; i > 0; i--) {
            long next = (c + n[i]) >> 1;
            n[i] = c;
            c = next;
        }
        for (int i = first; i <= last; i++) {
            int l = (int) hcode[i];
            if (l > 0) hcode[i] = l | n[l]++ << 6;
        }
    }

    private void buildDecodeTable(int im, int iM) throws IOException {
        Arrays.fill(decLength, 0);
        Arrays.fill(decSymbol, 0);
        Arrays.fill(decLong, null);
        // Long codes are counted per prefix first, so each prefix's list is allocated once.
        int[] longCount = decSymbol;
        for (int i = im; i <= iM; i++) {
            long code = hcode[i] >>> 6;
            int l = (int) (hcode[i] & 63);
            if (code >>> l != 0) throw new IOException("a Huffman code longer than its length");
            if (l > DEC_BITS) longCount[(int) (code >>> (l - DEC_BITS))]++;
        }
        for (int e = 0; e < DEC_SIZE; e++) {
            if (longCount[e] > 0) {
                decLong[e] = new int[longCount[e]];
                longCount[e] = 0;  // now the fill position
            }
        }
        for (int i = im; i <= iM; i++) {
            int l = (int) (hcode[i] & 63);
            if (l > DEC_BITS) {
                int e = (int) ((hcode[i] >>> 6) >>> (l - DEC_BITS));
                decLong[e][longCount[e]++] = i;
            }
        }
        Arrays.fill(decSymbol, 0);
        for (; im <= iM; im++) {
            long code = hcode[im] >>> 6;
            int l = (int) (hcode[im] & 63);
            if (l > 0 && l <= DEC_BITS) {
                int e = (int) (code << (DEC_BITS - l));
                for (int i = 0; i < 1 << (DEC_BITS - l); i++, e++) {
                    if (decLength[e] != 0 || decLong[e] != null) throw new IOException("two Huffman codes share a prefix");
                    decLength[e] = l;
                    decSymbol[e] = im;
                }
            }
        }
    }

    private void decodeSymbols(int nBits, int runCode, int count) throws IOException {
        bits = 0;
        bitCount = 0;
        outAt = 0;
        int ie = inAt + (int) ((nBits + 7L) / 8);
        while (inAt < ie) {
            bits = bits << 8 | (in[inAt++] & 0xFF);
            bitCount += 8;
            while (bitCount >= DEC_BITS) {
                int e = (int) (bits >>> (bitCount - DEC_BITS) & DEC_MASK);
                if (decLength[e] != 0) {
                    bitCount -= decLength[e];
                    put(decSymbol[e], runCode, count);
                } else {
                    int[] list = decLong[e];
                    if (list == null) throw new IOException("an invalid Huffman code");
                    boolean found = false;
                    for (int symbol : list) {
                        int l = (int) (hcode[symbol] & 63);
                        while (bitCount < l && inAt < ie) {
                            bits = bits << 8 | (in[inAt++] & 0xFF);
                            bitCount += 8;
                        }
                        if (bitCount >= l && hcode[symbol] >>> 6 == (bits >>> (bitCount - l) & ((1L << l) - 1))) {
                            bitCount -= l;
                            put(symbol, runCode, count);
                            found = true;
                            break;
                        }
                    }
                    if (!found) throw new IOException("an invalid Huffman code");
                }
            }
        }
        // The last byte's padding bits are dropped; the short codes left are decoded.
        int pad = (8 - nBits) & 7;
        bits >>>= pad;
        bitCount -= pad;
        while (bitCount > 0) {
            int e = (int) (bits << (DEC_BITS - bitCount) & DEC_MASK);
            if (decLength[e] == 0) throw new IOException("an invalid Huffman code");
            bitCount -= decLength[e];
            if (bitCount < 0) throw new IOException("an invalid Huffman code");
            put(decSymbol[e], runCode, count);
        }
        if (outAt != count) throw new IOException("the Huffman data hold " + outAt + " words, expected " + count);
    }

    /** Emits a symbol, or for the run code repeats the last word as often as the next 8 bits say. */
    private void put(int symbol, int runCode, int count) throws IOException {
        if (bitCount < 0) throw new IOException("an invalid Huffman code");
        if (symbol == runCode) {
            if (bitCount < 8) {
                needByte();
                bits = bits << 8 | (in[inAt++] & 0xFF);
                bitCount += 8;
            }
            bitCount -= 8;
            int run = (int) (bits >>> bitCount & 0xFF);
            if (run > count - outAt) throw new IOException("a run passes the block's " + count + " words");
            if (outAt == 0) throw new IOException("a run before the first word");
            Arrays.fill(words, outAt, outAt + run, words[outAt - 1]);
            outAt += run;
        } else {
            if (outAt >= count) throw new IOException("the Huffman data hold more than the block's " + count + " words");
            words[outAt++] = (char) symbol;
        }
    }
}
