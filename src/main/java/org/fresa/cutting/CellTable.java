package org.fresa.cutting;

/**
 * The cells of a grid by their packed key ({@link Chainer#pack}): an open-addressing table of
 * long keys and int arrays. Fenced fast path for the grids the rapid router and the lead test ask
 * a few hundred million times on the 50 MB sheet: a {@code HashMap<Long, int[]>} boxed the key of
 * every look-up and followed a node to a key object to compare it, which took 8 % of the run's CPU.
 */
final class CellTable {
    private long[] keys = new long[64];
    private int[][] values = new int[64][];
    private int size;

    /** The cell's array, or null. */
    int[] get(long key) {
        int mask = keys.length - 1;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            int[] v = values[i];
            if (v == null) {
                return null;
            }
            if (keys[i] == key) {
                return v;
            }
        }
    }

    /** Files the cell's array (not null) under its key, replacing any. */
    void put(long key, int[] value) {
        int mask = keys.length - 1;
        for (int i = slot(key, mask); ; i = (i + 1) & mask) {
            if (values[i] == null) {
                keys[i] = key;
                values[i] = value;
                if (++size * 2 > keys.length) {
                    grow();
                }
                return;
            }
            if (keys[i] == key) {
                values[i] = value;
                return;
            }
        }
    }

    private void grow() {
        long[] oldKeys = keys;
        int[][] oldValues = values;
        keys = new long[oldKeys.length * 2];
        values = new int[oldKeys.length * 2][];
        size = 0;
        for (int i = 0; i < oldKeys.length; i++) {
            if (oldValues[i] != null) {
                put(oldKeys[i], oldValues[i]);
            }
        }
    }

    private static int slot(long key, int mask) {
        long h = key * 0xBF58476D1CE4E5B9L;
        return (int) (h ^ (h >>> 31) ^ (h >>> 47)) & mask;
    }
}
