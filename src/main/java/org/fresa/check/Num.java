package org.fresa.check;

import java.math.BigDecimal;

/** Numbers in messages: up to three decimals, trailing zeros dropped, Locale-free. */
final class Num {

    private Num() {}

    static String of(double v) {
        if (!Double.isFinite(v)) {
            return Double.toString(v);
        }
        BigDecimal b = BigDecimal.valueOf(v)
                .setScale(3, java.math.RoundingMode.HALF_EVEN)
                .stripTrailingZeros();
        return b.signum() == 0 ? "0" : b.toPlainString();
    }

    static String deg(double v) {
        return String.format(java.util.Locale.ROOT, "%.1f", v);
    }
}
