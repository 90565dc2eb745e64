package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.util.ArrayList;
import java.util.List;
import org.junit.jupiter.api.Test;

/** The page growth of the store: values that straddle every kind of page edge decode as written. */
class InstanceStoreTest {

    private static final int MIB = 1 << 20;

    /** One instance: a record with a varint, a real of eight raw bytes and a text. */
    private static void write(InstanceStore s, int i) {
        s.beginInstance(i + 1, i + 1, 1, false);
        s.putString(InstanceStore.RECORD, "P");
        s.put(InstanceStore.BEGIN);
        s.putSigned(InstanceStore.INT, (long) i * 1_000_003L - 77);
        s.putReal(i + 0.1);
        s.putString(InstanceStore.TEXT, "t" + (i % 5));
        s.put(InstanceStore.END);
    }

    private static String expected(int i) {
        return "P(" + ((long) i * 1_000_003L - 77) + "," + (i + 0.1) + ",'t" + (i % 5) + "')";
    }

    private static String decoded(InstanceStore s, int i) {
        StepRecord r = s.instanceAt(i).record();
        StringBuilder sb = new StringBuilder(r.type()).append('(');
        for (int k = 0; k < r.params().size(); k++) {
            sb.append(k > 0 ? "," : "").append(r.param(k));
        }
        return sb.append(')').toString();
    }

    @Test
    void aSmallStoreHoldsOneSmallPage() {
        InstanceStore s = new InstanceStore();
        for (int i = 0; i < 10; i++) {
            write(s, i);
        }
        assertEquals(InstanceStore.FIRST_PAGE, s.capacity());
        for (int i = 0; i < 10; i++) {
            assertEquals(expected(i), decoded(s, i));
        }
    }

    @Test
    void valuesAcrossTheGrowthOfTheFirstPageAndAcrossPageEdgesDecodeAsWritten() {
        InstanceStore s = new InstanceStore();
        List<Integer> straddling = new ArrayList<>();
        int strictly = 0;
        int n = 0;
        // every size the first page passes through, then the first two 1 MiB edges; the instances
        // differ in length, so some straddle an edge and some end on one
        List<Integer> edges = new ArrayList<>();
        for (int e = InstanceStore.FIRST_PAGE; e <= MIB; e *= 2) {
            edges.add(e);
        }
        edges.add(2 * MIB);
        while (s.size() < 2 * MIB + 100) {
            int before = s.size();
            write(s, n);
            for (int e : edges) {
                if (before < e && s.size() >= e) {
                    straddling.add(n);
                    strictly += s.size() > e ? 1 : 0;
                }
            }
            n++;
        }
        assertEquals(edges.size(), straddling.size(), "one instance reaches each edge");
        assertTrue(strictly >= edges.size() / 2, strictly + " instances straddle an edge");
        // two full pages and the start of a third, never more than one page to spare
        assertEquals(3L * MIB, s.capacity());
        for (int i = 0; i < n; i++) {
            assertEquals(expected(i), decoded(s, i), "instance " + i);
        }
        assertTrue(s.indexOf(n) == n - 1 && s.lineAt(n - 1) == n);
    }
}
