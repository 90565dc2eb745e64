package org.fresa.pocket;

import java.util.List;

class DebugMain2 {
    public static void main(String[] args) throws Exception {
        PocketProfile p = RecognitionTest.sample("cavity02.dad");
        List<PocketElement> e = p.elements();
        System.err.println(e + " compar " + p.compar());
        int n = e.size();
        for (int i = 0; i < n; i++) {
            PocketElement a = e.get((i + n - 1) % n), b = e.get(i), c = e.get((i + 1) % n);
            for (Incentres.Solution s : Incentres.of(a, b, c)) {
                System.err.println(b + " " + s + " j1=" + ElementGeometry.junction(a, b, s.t(), p.compar()) + " j2=" + ElementGeometry.junction(b, c, s.t(), p.compar()));
            }
        }
    }
}
