package org.fresa.cutting;

/**
 * The indices of an array of keys in the order of their keys, ties in index order: what a stable
 * sort of boxed indices by {@code Comparator.comparingDouble} gives, without a boxed integer and
 * a comparator call per comparison (727 000 curve boxes of the 50 MB sheet are sorted this way).
 */
final class IndexSort {
    private IndexSort() {}

    /** 0 .. key.length - 1 sorted by key (as {@link Double#compare} orders them), stable. */
    static int[] byKey(double[] key) {
        int n = key.length;
        int[] order = new int[n];
        for (int i = 0; i < n; i++) {
            order[i] = i;
        }
        int[] tmp = new int[n];
        // bottom-up merge sort: runs of 16 by insertion, then merged pairwise
        for (int from = 0; from < n; from += 16) {
            int to = Math.min(n, from + 16);
            for (int i = from + 1; i < to; i++) {
                int v = order[i];
                int j = i - 1;
                while (j >= from && Double.compare(key[order[j]], key[v]) > 0) {
                    order[j + 1] = order[j];
                    j--;
                }
                order[j + 1] = v;
            }
        }
        int[] src = order;
        int[] dst = tmp;
        for (int width = 16; width < n; width *= 2) {
            for (int from = 0; from < n; from += 2 * width) {
                int mid = Math.min(n, from + width);
                int to = Math.min(n, from + 2 * width);
                int i = from;
                int j = mid;
                for (int k = from; k < to; k++) {
                    if (j >= to || i < mid && Double.compare(key[src[i]], key[src[j]]) <= 0) {
                        dst[k] = src[i++];
                    } else {
                        dst[k] = src[j++];
                    }
                }
            }
            int[] s = src;
            src = dst;
            dst = s;
        }
        return src;
    }
}
