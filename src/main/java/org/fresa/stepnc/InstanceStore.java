package org.fresa.stepnc;

import java.util.ArrayList;
import java.util.Arrays;
import java.util.HashMap;
import java.util.List;
import java.util.Map;

/**
 * The data section of a Part 21 file in compact form: each instance's records as a byte-coded
 * token stream (tag byte, then a varint or the raw bits of a real) in pages of at most 1 MiB, its name, line
 * and column in primitive arrays, names found through an open-addressing hash table. Strings,
 * keywords and enumeration names are pooled once. {@link StepInstance}s are decoded on demand and
 * not kept, so a large file costs a few bytes per token instead of an object graph.
 *
 * <p>The stream is written only by {@link Part21Reader} after the syntax has been checked, so
 * decoding never fails.
 */
final class InstanceStore {

    // tags of the token stream
    static final byte SIMPLE = 1;
    static final byte COMPLEX = 2;
    static final byte RECORD = 3;
    static final byte BEGIN = 4;
    static final byte END = 5;
    static final byte UNSET = 6;
    static final byte DERIVED = 7;
    static final byte INT = 8;
    static final byte REAL_INT = 9;
    static final byte REAL32 = 10;
    static final byte REAL64 = 11;
    static final byte TEXT = 12;
    static final byte ENUM = 13;
    static final byte BINARY = 14;
    static final byte REF = 15;
    static final byte TYPED = 16;
    static final byte REAL_MINUS_ZERO = 17;

    private static final int PAGE_BITS = 20;
    private static final int PAGE = 1 << PAGE_BITS;
    private static final int PAGE_MASK = PAGE - 1;
    // the last page starts this small and doubles up to PAGE: a small file, the usual case, would
    // otherwise clear a whole MiB per read for a few KiB of tokens
    static final int FIRST_PAGE = 4096;

    private byte[][] pages = new byte[4][];
    private int size;
    // the page being written and the position where its array ends: one compare per put
    private byte[] page;
    private int limit;

    private long[] ids = new long[256];
    private int[] starts = new int[256];
    private int[] lines = new int[256];
    private int[] cols = new int[256];
    private int count;

    private long[] keys = new long[512];
    private int[] slots = new int[512];

    private final List<String> strings = new ArrayList<>();
    private final Map<String, Integer> stringIndex = new HashMap<>();
    // the decoded values of the pooled strings, shared by every decoded instance
    private final List<StepValue> textValues = new ArrayList<>();
    private final List<StepValue> enumValues = new ArrayList<>();

    int count() {
        return count;
    }

    long idAt(int i) {
        return ids[i];
    }

    int lineAt(int i) {
        return lines[i];
    }

    int columnAt(int i) {
        return cols[i];
    }

    /** The index of instance #id in file order, or -1. */
    int indexOf(long id) {
        int mask = keys.length - 1;
        int h = hash(id) & mask;
        while (true) {
            long k = keys[h];
            if (k == id) {
                return slots[h];
            }
            if (k == 0) {
                return -1;
            }
            h = (h + 1) & mask;
        }
    }

    private static int hash(long id) {
        long x = id * 0x9E3779B97F4A7C15L;
        return (int) (x ^ (x >>> 32));
    }

    // ---- writing ----

    /** Starts instance #id (not yet defined: the caller checked). */
    void beginInstance(long id, int line, int col, boolean complex) {
        if (count == ids.length) {
            int m = count * 2;
            ids = Arrays.copyOf(ids, m);
            starts = Arrays.copyOf(starts, m);
            lines = Arrays.copyOf(lines, m);
            cols = Arrays.copyOf(cols, m);
        }
        ids[count] = id;
        starts[count] = size;
        lines[count] = line;
        cols[count] = col;
        putIndex(id, count);
        count++;
        put(complex ? COMPLEX : SIMPLE);
    }

    private void putIndex(long id, int index) {
        if ((count + 1) * 2 > keys.length) {
            long[] oldKeys = keys;
            int[] oldSlots = slots;
            keys = new long[oldKeys.length * 2];
            slots = new int[oldKeys.length * 2];
            for (int i = 0; i < oldKeys.length; i++) {
                if (oldKeys[i] != 0) {
                    insert(oldKeys[i], oldSlots[i]);
                }
            }
        }
        insert(id, index);
    }

    private void insert(long id, int index) {
        int mask = keys.length - 1;
        int h = hash(id) & mask;
        while (keys[h] != 0) {
            h = (h + 1) & mask;
        }
        keys[h] = id;
        slots[h] = index;
    }

    void put(byte b) {
        if (size >= limit) {
            nextPage();
        }
        page[size & PAGE_MASK] = b;
        size++;
    }

    /** Makes room for the byte at size: a new page at a page boundary, else a larger last page. */
    private void nextPage() {
        int p = size >>> PAGE_BITS;
        if (p == pages.length) {
            pages = Arrays.copyOf(pages, p * 2);
        }
        byte[] cur = pages[p];
        if (cur == null) {
            cur = new byte[p == 0 ? FIRST_PAGE : PAGE];
        } else {
            cur = Arrays.copyOf(cur, Math.min(PAGE, cur.length * 2));
        }
        pages[p] = cur;
        page = cur;
        limit = (p << PAGE_BITS) + cur.length;
    }

    /** Bytes written so far. */
    int size() {
        return size;
    }

    /** The bytes held by the pages (at least size()), for tests of the growth. */
    long capacity() {
        long c = 0;
        for (byte[] pg : pages) {
            c += pg == null ? 0 : pg.length;
        }
        return c;
    }

    void putVar(long v) {
        while ((v & ~0x7FL) != 0) {
            put((byte) ((v & 0x7F) | 0x80));
            v >>>= 7;
        }
        put((byte) v);
    }

    void putTagged(byte tag, long v) {
        put(tag);
        putVar(v);
    }

    void putSigned(byte tag, long v) {
        put(tag);
        putVar((v << 1) ^ (v >> 63));
    }

    void putReal(double d) {
        long bits = Double.doubleToRawLongBits(d);
        if (bits == 0x8000000000000000L) {
            put(REAL_MINUS_ZERO);
        } else if (d == (int) d) {
            putSigned(REAL_INT, (int) d);
        } else if ((double) (float) d == d) {
            put(REAL32);
            int f = Float.floatToRawIntBits((float) d);
            for (int s = 0; s < 32; s += 8) {
                put((byte) (f >>> s));
            }
        } else {
            put(REAL64);
            for (int s = 0; s < 64; s += 8) {
                put((byte) (bits >>> s));
            }
        }
    }

    void putString(byte tag, String s) {
        Integer k = stringIndex.get(s);
        if (k == null) {
            k = strings.size();
            strings.add(s);
            stringIndex.put(s, k);
            textValues.add(null);
            enumValues.add(null);
        }
        putTagged(tag, k);
    }

    // ---- reading ----

    private byte at(int pos) {
        return pages[pos >>> PAGE_BITS][pos & PAGE_MASK];
    }

    boolean isComplexAt(int i) {
        return at(starts[i]) == COMPLEX;
    }

    /** The keyword of the first record of instance i, without decoding its parameters. */
    String firstTypeAt(int i) {
        Cursor c = new Cursor(starts[i] + 1);
        if (at(c.pos) == COMPLEX) {
            c.pos++;
        }
        c.pos++;
        return strings.get((int) c.var());
    }

    // the instances decoded last, by index modulo its size: the binding asks for many twice
    private final StepInstance[] recent = new StepInstance[1024];

    StepInstance instanceAt(int i) {
        int slot = i & (recent.length - 1);
        StepInstance r = recent[slot];
        if (r != null && r.id() == ids[i]) {
            return r;
        }
        r = decode(i);
        recent[slot] = r;
        return r;
    }

    private StepInstance decode(int i) {
        int end = i + 1 < count ? starts[i + 1] : size;
        Cursor c = new Cursor(starts[i]);
        long id = ids[i];
        boolean complex = at(c.pos++) == COMPLEX;
        List<StepRecord> records = complex ? new ArrayList<>() : null;
        StepRecord single = null;
        while (c.pos < end) {
            c.pos++; // RECORD
            String type = strings.get((int) c.var());
            c.pos++; // BEGIN
            StepRecord r = new StepRecord(type, c.items(id));
            if (complex) {
                records.add(r);
            } else {
                single = r;
            }
        }
        return new StepInstance(id, complex ? records : List.of(single), lines[i], cols[i]);
    }

    private StepValue text(int k) {
        StepValue v = textValues.get(k);
        if (v == null) {
            v = new StepValue.Text(strings.get(k));
            textValues.set(k, v);
        }
        return v;
    }

    private StepValue enumeration(int k) {
        StepValue v = enumValues.get(k);
        if (v == null) {
            v = new StepValue.Enumeration(strings.get(k));
            enumValues.set(k, v);
        }
        return v;
    }

    /**
     * An unmodifiable list of a[f, f + n): up to ten items through List.of's fixed-arity
     * forms, which keep their array, so StepRecord's and Aggregate's List.copyOf return it as is.
     */
    static List<StepValue> listOf(StepValue[] a, int f, int n) {
        return switch (n) {
            case 0 -> List.of();
            case 1 -> List.of(a[f]);
            case 2 -> List.of(a[f], a[f + 1]);
            case 3 -> List.of(a[f], a[f + 1], a[f + 2]);
            case 4 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3]);
            case 5 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4]);
            case 6 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4], a[f + 5]);
            case 7 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4], a[f + 5], a[f + 6]);
            case 8 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4], a[f + 5], a[f + 6], a[f + 7]);
            case 9 -> List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4], a[f + 5], a[f + 6], a[f + 7], a[f + 8]);
            case 10 ->
                List.of(a[f], a[f + 1], a[f + 2], a[f + 3], a[f + 4], a[f + 5], a[f + 6], a[f + 7], a[f + 8], a[f + 9]);
            default -> List.of(Arrays.copyOfRange(a, f, f + n));
        };
    }

    private static final StepValue.Real ZERO = new StepValue.Real(0.0);
    private static final StepValue.Real ONE = new StepValue.Real(1.0);
    private static final StepValue.Real MINUS_ONE = new StepValue.Real(-1.0);

    private final class Cursor {
        int pos;
        // the items of the lists being decoded, nested ones above their parent's: each list is
        // then built once, at its size, instead of through an ArrayList and List.copyOf's copies
        private StepValue[] stack;
        private int top;

        Cursor(int pos) {
            this.pos = pos;
        }

        long var() {
            long v = 0;
            int shift = 0;
            while (true) {
                byte b = at(pos++);
                v |= (long) (b & 0x7F) << shift;
                if (b >= 0) {
                    return v;
                }
                shift += 7;
            }
        }

        long signed() {
            long z = var();
            return (z >>> 1) ^ -(z & 1);
        }

        /** The items up to the END that closes the list whose BEGIN was just read. */
        List<StepValue> items(long self) {
            if (stack == null) {
                stack = new StepValue[32];
            }
            int base = top;
            while (at(pos) != END) {
                StepValue v = value(self);
                if (top == stack.length) {
                    stack = Arrays.copyOf(stack, top * 2);
                }
                stack[top++] = v;
            }
            pos++;
            List<StepValue> items = listOf(stack, base, top - base);
            top = base;
            return items;
        }

        StepValue value(long self) {
            byte tag = at(pos++);
            switch (tag) {
                case UNSET:
                    return StepValue.UNSET;
                case DERIVED:
                    return StepValue.DERIVED;
                case INT:
                    return new StepValue.Int(signed());
                case REAL_INT: {
                    long v = signed();
                    return v == 0 ? ZERO : v == 1 ? ONE : v == -1 ? MINUS_ONE : new StepValue.Real(v);
                }
                case REAL_MINUS_ZERO:
                    return new StepValue.Real(-0.0);
                case REAL32: {
                    int f = 0;
                    for (int s = 0; s < 32; s += 8) {
                        f |= (at(pos++) & 0xFF) << s;
                    }
                    return new StepValue.Real(Float.intBitsToFloat(f));
                }
                case REAL64: {
                    long b = 0;
                    for (int s = 0; s < 64; s += 8) {
                        b |= (long) (at(pos++) & 0xFF) << s;
                    }
                    return new StepValue.Real(Double.longBitsToDouble(b));
                }
                case TEXT:
                    return text((int) var());
                case ENUM:
                    return enumeration((int) var());
                case BINARY:
                    return new StepValue.Binary(strings.get((int) var()));
                case REF:
                    return new StepValue.Ref(self + signed());
                case TYPED: {
                    String type = strings.get((int) var());
                    return new StepValue.Typed(type, value(self));
                }
                case BEGIN:
                    return new StepValue.Aggregate(items(self));
                default:
                    throw new IllegalStateException("corrupt instance store: tag " + tag + " at " + (pos - 1));
            }
        }
    }
}
