package lt.spindulys.io;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import java.util.Random;

import org.junit.jupiter.api.Test;

import lt.spindulys.math.Ranges;
import lt.spindulys.mesh.MeshData;

/**
 * The hand-written number parser gives exactly {@link Double#parseDouble}'s double (correct
 * rounding) for every shape of token the OBJ grammar accepts: signs, leading zeros, long
 * mantissas, '.5' and '5.', exponents of both signs and cases, subnormals and underflow to zero.
 */
class ObjReaderNumbersTest {

    private static String digits(Random r, int n) {
        StringBuilder s = new StringBuilder(n);
        for (int i = 0; i < n; i++) s.append((char) ('0' + r.nextInt(10)));
        return s.toString();
    }

    /** A random token in the grammar [+-] digits [. digits] [e [+-] digits], with at least one mantissa digit. */
    private static String token(Random r) {
        StringBuilder s = new StringBuilder();
        switch (r.nextInt(4)) {
            case 0 -> s.append('-');
            case 1 -> s.append('+');
            default -> { }
        }
        // Lengths favour the fast path's edge (15 significant digits) and go well past 19.
        int intDigits = switch (r.nextInt(5)) {
            case 0 -> 0;
            case 1 -> 1;
            case 2 -> r.nextInt(8);
            case 3 -> 13 + r.nextInt(5);
            default -> r.nextInt(26);
        };
        if (r.nextInt(6) == 0) s.append("000".substring(r.nextInt(3))); // leading zeros
        s.append(digits(r, intDigits));
        int fracDigits = -1;
        if (intDigits == 0 || r.nextInt(3) > 0) {
            fracDigits = switch (r.nextInt(5)) {
                case 0 -> 0; // "5."
                case 1 -> 1 + r.nextInt(6);
                case 2 -> 13 + r.nextInt(5);
                default -> r.nextInt(30);
            };
            if (intDigits == 0 && fracDigits == 0) fracDigits = 1 + r.nextInt(20); // ".5"
            s.append('.');
            if (r.nextInt(5) == 0) s.append("0000000".substring(r.nextInt(7))); // 0.000ddd
            s.append(digits(r, fracDigits));
        }
        if (intDigits == 0 && fracDigits <= 0) s.append('7');
        if (r.nextInt(3) == 0) {
            s.append(r.nextBoolean() ? 'e' : 'E');
            if (r.nextInt(3) == 0) s.append(r.nextBoolean() ? '-' : '+');
            int e = switch (r.nextInt(4)) {
                case 0 -> r.nextInt(23);  // the fast path's powers
                case 1 -> 23 + r.nextInt(10);
                case 2 -> 290 + r.nextInt(60); // subnormals and underflow (with '-')
                default -> r.nextInt(400);
            };
            s.append(r.nextInt(8) == 0 ? "0" : "").append(e);
        }
        return s.toString();
    }

    @Test
    void randomTokensGiveParseDoublesValue() {
        Random r = new Random(20261202);
        List<String> tokens = new ArrayList<>();
        int tooLarge = 0;
        while (tokens.size() < 200_000) {
            String t = token(r);
            if (Math.abs(Double.parseDouble(t)) <= Ranges.MAX_NUMBER) tokens.add(t);
            else tooLarge++;
        }
        // Hard cases: halfway between doubles, the smallest normal and subnormal, underflow.
        String[] hard = {"562949953421312.0625", "562949953421312.0625000000000001", "562949953421312.1875", "0.1", "0.30000000000000004", "2.2250738585072011e-308",
            "2.2250738585072012e-308", "4.9e-324", "2.4703282292062327e-324", "2.4703282292062328e-324", "1e-400", "-1e-400",
            "-0", "+0.0", "123456789012345", "123456789012345.6", "0.000000000000000000000000000001", "1e-22", "1e-23", "1e15", "-1e15", "0.00001e20", "999999999999999e-22",
            "1.00000000000000011102230246251565404236316680908203125", "1.00000000000000011102230246251565404236316680908203124",
            ".5", "5.", "-.5e1", "00000000000000000000000000001.5"};
        for (String h : hard) tokens.add(h);
        while (tokens.size() % 3 != 0) tokens.add("1");
        StringBuilder s = new StringBuilder();
        for (int i = 0; i < tokens.size(); i += 3) s.append("v ").append(tokens.get(i)).append(' ').append(tokens.get(i + 1)).append(' ').append(tokens.get(i + 2)).append('\n');
        MeshData m = ObjReader.parse(s.toString(), "n.obj");
        double[] p = m.positions();
        assertEquals(tokens.size(), p.length);
        for (int i = 0; i < p.length; i++) {
            String t = tokens.get(i);
            assertEquals(Double.doubleToRawLongBits(Double.parseDouble(t)), Double.doubleToRawLongBits(p[i]), () -> "token " + t);
        }
        assertTrue(tooLarge > 1000, "the shapes reach past the mesh limit too: " + tooLarge);
    }

    @Test
    void numbersPastTheMeshLimitAreRefusedWhateverTheirForm() {
        for (String t : new String[] {"1000000000000001", "1.0000000000000001e15", "1e16", "-2e15", "1.7976931348623157e308", "1e400"}) {
            SceneException e = assertThrows(SceneException.class, () -> ObjReader.parse("v 0 " + t + " 0\n", "big.obj"), t);
            assertEquals("big.obj:1:5: number " + t + " is too large for vertex y (mesh numbers are at most 1e15 in magnitude)", e.getMessage());
        }
    }
}
