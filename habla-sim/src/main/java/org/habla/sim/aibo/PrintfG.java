package org.habla.sim.aibo;

import java.math.BigDecimal;
import java.math.MathContext;
import java.math.RoundingMode;

/**
 * A number as C's {@code printf("%g")} prints it, which is how Tekkotsu writes the numbers of a posture
 * ({@code #POS} sensor strings): six significant digits, rounded from the exact binary value; scientific
 * ({@code 1.23457e+08}, {@code 1e-05}) when the decimal exponent is below −4 or at least 6, plain otherwise
 * ({@code 1500}, {@code 0.523599}); trailing zeros and a bare decimal point dropped. Java's own {@code %g}
 * keeps the zeros and switches notation at other exponents, so it cannot be used.
 */
final class PrintfG {

    /** Significant digits of {@code %g} without a precision. */
    static final int PRECISION = 6;

    private PrintfG() {
    }

    static String of(double v) {
        if (Double.isNaN(v)) {
            return "nan";
        }
        if (Double.isInfinite(v)) {
            return v > 0 ? "inf" : "-inf";
        }
        if (v == 0) {
            return 1 / v < 0 ? "-0" : "0";
        }
        BigDecimal rounded = new BigDecimal(v).round(new MathContext(PRECISION, RoundingMode.HALF_EVEN));
        int exponent = rounded.precision() - rounded.scale() - 1;
        if (exponent < -4 || exponent >= PRECISION) {
            String mantissa = stripZeros(rounded.movePointLeft(exponent).setScale(PRECISION - 1, RoundingMode.UNNECESSARY)
                    .toPlainString());
            int e = Math.abs(exponent);
            return mantissa + "e" + (exponent < 0 ? "-" : "+") + (e < 10 ? "0" : "") + e;
        }
        return stripZeros(rounded.setScale(PRECISION - 1 - exponent, RoundingMode.UNNECESSARY).toPlainString());
    }

    private static String stripZeros(String s) {
        if (s.indexOf('.') < 0) {
            return s;
        }
        int end = s.length();
        while (s.charAt(end - 1) == '0') {
            end--;
        }
        if (s.charAt(end - 1) == '.') {
            end--;
        }
        return s.substring(0, end);
    }
}
