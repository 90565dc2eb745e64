package org.fresa.chart;

import java.io.Serializable;
import java.text.DecimalFormat;
import java.text.DecimalFormatSymbols;
import java.text.NumberFormat;
import java.util.Locale;
import org.jfree.chart.axis.NumberAxis;
import org.jfree.chart.axis.NumberTickUnit;
import org.jfree.chart.axis.NumberTickUnitSource;
import org.jfree.chart.axis.TickUnit;
import org.jfree.chart.axis.TickUnitSource;

/**
 * Number axes whose tick labels read the same on every machine: JFreeChart formats them in the
 * default locale, so a German machine labelled the error axis "5,5E-10" and the point axis
 * "1.000" (a thousand) where the legends and every file the application writes say 5.5e-10 and
 * 1000. The ticks are JFreeChart's own (1, 2 or 5 times a power of ten, its patterns per power);
 * only their symbols are those of {@link Locale#ROOT}.
 */
public final class NumberAxes {

    private NumberAxes() {}

    /** A number axis with this label and tick labels in {@link Locale#ROOT}. */
    public static NumberAxis of(String label) {
        NumberAxis a = new NumberAxis(label);
        a.setStandardTickUnits(new RootTickUnits());
        return a;
    }

    /**
     * JFreeChart's tick units ({@link NumberTickUnitSource}), each given the pattern that source
     * gives its power of ten, with the symbols of {@link Locale#ROOT}.
     */
    private static final class RootTickUnits implements TickUnitSource, Serializable {
        private static final long serialVersionUID = 1L;
        private static final DecimalFormatSymbols ROOT = DecimalFormatSymbols.getInstance(Locale.ROOT);

        private final NumberTickUnitSource units = new NumberTickUnitSource();
        // per instance, as the source's own: a DecimalFormat is not for two threads at once
        private final DecimalFormat tenThousandths = new DecimalFormat("0.0000", ROOT);
        private final DecimalFormat thousandths = new DecimalFormat("0.000", ROOT);
        private final DecimalFormat hundredths = new DecimalFormat("0.00", ROOT);
        private final DecimalFormat tenths = new DecimalFormat("0.0", ROOT);
        private final DecimalFormat whole = new DecimalFormat("#,##0", ROOT);
        private final DecimalFormat scientific = new DecimalFormat("#.######E0", ROOT);

        @Override
        public TickUnit getLargerTickUnit(TickUnit unit) {
            // the source's own unit of that size, then the next: the source tells its larger unit
            // by comparing the formats too, which are not its own here
            TickUnit same = units.getCeilingTickUnit(unit.getSize());
            return root(same.getSize() > unit.getSize() ? same : units.getLargerTickUnit(same));
        }

        @Override
        public TickUnit getCeilingTickUnit(TickUnit unit) {
            return getCeilingTickUnit(unit.getSize());
        }

        @Override
        public TickUnit getCeilingTickUnit(double size) {
            return root(units.getCeilingTickUnit(size));
        }

        private NumberTickUnit root(TickUnit unit) {
            return new NumberTickUnit(unit.getSize(), format(unit.getSize()), unit.getMinorTickCount());
        }

        /** The pattern NumberTickUnitSource gives a unit of this size (1, 2 or 5 times 10^power). */
        private NumberFormat format(double size) {
            // the size is the product factor * 10^power, a hair off the exact power at most
            int power = (int) Math.floor(Math.log10(size) + 1e-9);
            return switch (power) {
                case -4 -> tenThousandths;
                case -3 -> thousandths;
                case -2 -> hundredths;
                case -1 -> tenths;
                case 0, 1, 2, 3, 4, 5, 6 -> whole;
                default -> scientific;
            };
        }

        @Override
        public boolean equals(Object o) {
            return o instanceof RootTickUnits;
        }

        @Override
        public int hashCode() {
            return RootTickUnits.class.hashCode();
        }
    }
}
