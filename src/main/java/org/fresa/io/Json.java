package org.fresa.io;

import java.util.Iterator;
import java.util.List;
import java.util.Map;
import org.fresa.model.ExactDecimal;

/**
 * Writes JSON from maps, lists, strings, numbers and booleans: the {@code --json} summaries and
 * {@code summary.json}. Doubles are written exactly (shortest round-trip decimal, Locale-free);
 * NaN and infinities, which JSON cannot hold, are written as null.
 */
public final class Json {
    private Json() {}

    /** Above this many characters the text built so far goes to the writer, when there is one. */
    private static final int SPILL_CHARS = 1 << 16;

    public static String write(Object value) {
        StringBuilder sb = new StringBuilder();
        append(sb, value, 0, false, null);
        return sb.toString();
    }

    /** Indented, for files people read. */
    public static String writePretty(Object value) {
        StringBuilder sb = new StringBuilder();
        append(sb, value, 0, true, null);
        return sb.append('\n').toString();
    }

    /**
     * {@link #writePretty(Object)} into a writer, a part at a time: the same text, without holding
     * the whole of a large summary as one string.
     */
    public static void writePretty(Object value, java.io.Writer out) throws java.io.IOException {
        StringBuilder sb = new StringBuilder();
        try {
            append(sb, value, 0, true, out);
        } catch (java.io.UncheckedIOException e) {
            throw e.getCause();
        }
        out.write(sb.append('\n').toString());
        out.flush();
    }

    /** Passes what is built to the writer once it is long. */
    private static void spill(StringBuilder sb, java.io.Writer out) {
        if (out != null && sb.length() > SPILL_CHARS) {
            try {
                out.write(sb.toString());
            } catch (java.io.IOException e) {
                throw new java.io.UncheckedIOException(e);
            }
            sb.setLength(0);
        }
    }

    /**
     * The map in an order that is the same in every run: a {@code Map.of} (whose iteration order is
     * salted per JVM run) by its keys' names; any other map (LinkedHashMap, TreeMap) as it is.
     */
    public static Map<?, ?> inStableOrder(Map<?, ?> m) {
        if (!m.getClass().getName().startsWith("java.util.ImmutableCollections")) {
            return m;
        }
        Map<Object, Object> sorted = new java.util.TreeMap<>(java.util.Comparator.comparing(String::valueOf));
        sorted.putAll(m);
        return sorted;
    }

    private static void append(StringBuilder sb, Object v, int indent, boolean pretty, java.io.Writer out) {
        if (v == null) {
            sb.append("null");
        } else if (v instanceof String s) {
            quote(sb, s);
        } else if (v instanceof Double || v instanceof Float) {
            double d = ((Number) v).doubleValue();
            sb.append(Double.isFinite(d) ? ExactDecimal.of(d) : "null");
        } else if (v instanceof Number || v instanceof Boolean) {
            sb.append(v);
        } else if (v instanceof Map<?, ?> m) {
            sb.append('{');
            Iterator<? extends Map.Entry<?, ?>> it = inStableOrder(m).entrySet().iterator();
            boolean first = true;
            while (it.hasNext()) {
                Map.Entry<?, ?> e = it.next();
                if (!first) {
                    sb.append(',');
                }
                first = false;
                newline(sb, indent + 1, pretty);
                quote(sb, String.valueOf(e.getKey()));
                sb.append(pretty ? ": " : ":");
                append(sb, e.getValue(), indent + 1, pretty, out);
                spill(sb, out);
            }
            if (!m.isEmpty()) {
                newline(sb, indent, pretty);
            }
            sb.append('}');
        } else if (v instanceof List<?> l) {
            sb.append('[');
            for (int i = 0; i < l.size(); i++) {
                if (i > 0) {
                    sb.append(pretty ? ", " : ",");
                }
                append(sb, l.get(i), indent + 1, pretty, out);
                spill(sb, out);
            }
            sb.append(']');
        } else if (v instanceof double[] a) {
            sb.append('[');
            for (int i = 0; i < a.length; i++) {
                if (i > 0) {
                    sb.append(pretty ? ", " : ",");
                }
                append(sb, a[i], indent, pretty, out);
            }
            sb.append(']');
        } else if (v instanceof Enum<?> e) {
            quote(sb, e.name());
        } else {
            quote(sb, v.toString());
        }
    }

    private static void newline(StringBuilder sb, int indent, boolean pretty) {
        if (pretty) {
            sb.append('\n');
            for (int i = 0; i < indent; i++) {
                sb.append("  ");
            }
        }
    }

    private static void quote(StringBuilder sb, String s) {
        sb.append('"');
        for (int i = 0; i < s.length(); i++) {
            char c = s.charAt(i);
            switch (c) {
                case '"' -> sb.append("\\\"");
                case '\\' -> sb.append("\\\\");
                case '\n' -> sb.append("\\n");
                case '\r' -> sb.append("\\r");
                case '\t' -> sb.append("\\t");
                default -> {
                    if (c < 0x20) {
                        sb.append(String.format(java.util.Locale.ROOT, "\\u%04x", (int) c));
                    } else {
                        sb.append(c);
                    }
                }
            }
        }
        sb.append('"');
    }
}
