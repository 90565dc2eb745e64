package org.fresa.stepnc;

import java.util.List;
import java.util.Objects;

/**
 * One parameter of a Part 21 record, exactly as written: no schema knowledge. Booleans and
 * logicals are enumerations ({@code .T.}, {@code .F.}, {@code .U.}).
 */
public sealed interface StepValue {

    /** Whether the attribute is left without a value of its own: unset ({@code $}) or derived ({@code *}). */
    default boolean absent() {
        return this instanceof Unset || this instanceof Derived;
    }

    /** {@code $}: the attribute has no value. */
    record Unset() implements StepValue {
        @Override
        public String toString() {
            return "$";
        }
    }

    /** {@code *}: the value is derived by a supertype's rule. */
    record Derived() implements StepValue {
        @Override
        public String toString() {
            return "*";
        }
    }

    record Int(long value) implements StepValue {
        @Override
        public String toString() {
            return Long.toString(value);
        }
    }

    /** A finite real; the reader rejects values outside the double range. */
    record Real(double value) implements StepValue {
        @Override
        public String toString() {
            return Double.toString(value);
        }
    }

    /** A string with every escape decoded. */
    record Text(String value) implements StepValue {
        public Text {
            Objects.requireNonNull(value, "value");
        }

        @Override
        public String toString() {
            return "'" + value.replace("'", "''") + "'";
        }
    }

    /** {@code .NAME.}, the name without the dots, upper case. */
    record Enumeration(String name) implements StepValue {
        public Enumeration {
            Objects.requireNonNull(name, "name");
        }

        @Override
        public String toString() {
            return "." + name + ".";
        }
    }

    /** {@code "0F3"}: a binary as its hexadecimal text (first digit: unused bits). */
    record Binary(String hex) implements StepValue {
        public Binary {
            Objects.requireNonNull(hex, "hex");
        }
    }

    /** {@code #id}: a reference to an entity instance. */
    record Ref(long id) implements StepValue {
        @Override
        public String toString() {
            return "#" + id;
        }
    }

    /** {@code (a, b, ...)}: a list, set, bag or array. */
    record Aggregate(List<StepValue> items) implements StepValue {
        public Aggregate {
            items = List.copyOf(items);
        }

        @Override
        public String toString() {
            StringBuilder sb = new StringBuilder("(");
            for (int i = 0; i < items.size(); i++) {
                sb.append(i > 0 ? "," : "").append(items.get(i));
            }
            return sb.append(')').toString();
        }
    }

    /** {@code LENGTH_MEASURE(2.)}: a value of a defined type named in the file. */
    record Typed(String type, StepValue value) implements StepValue {
        public Typed {
            Objects.requireNonNull(type, "type");
            Objects.requireNonNull(value, "value");
        }

        @Override
        public String toString() {
            return type + "(" + value + ")";
        }
    }

    StepValue UNSET = new Unset();
    StepValue DERIVED = new Derived();
}
