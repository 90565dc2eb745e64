package org.fresa.pocket;

import java.util.List;
import java.util.Locale;
import java.util.Random;
import org.fresa.geom.Contour;
import org.fresa.model.Move;
import org.fresa.model.ToolpathSection;
import org.junit.jupiter.api.Test;

class ScratchAdaptiveSurvey {
    @Test
    void survey() throws Exception {
        Random rnd = new Random(Long.getLong("seed", 21));
        int n = Integer.getInteger("count", 30);
        int done = 0;
        for (int attempt = 0; done < n && attempt < 3 * n; attempt++) {
            List<Contour> p = PocketCleanUpTest.pocket(rnd);
            PocketTechnology t = PocketCleanUpTest.tech(rnd);
            try {
                RegionPocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT, true);
            } catch (ToolTooLargeException | IllegalArgumentException e) {
                continue;
            }
            long t0 = System.nanoTime();
            String res;
            try {
                AdaptivePocket.Plan plan =
                        AdaptivePocket.plan(p.get(0), p.subList(1, p.size()), t, true, EntryRule.DEFAULT);
                res = verdict(p, t, plan);
            } catch (ToolTooLargeException e) {
                res = "REFUSED " + e.getMessage();
            }
            System.out.printf(
                    Locale.ROOT,
                    "SURVEY %2d i%d cut %.2f %5.1fs %s%n",
                    done,
                    p.size() - 1,
                    t.cutFraction(),
                    (System.nanoTime() - t0) / 1e9,
                    res);
            done++;
        }
    }

    static String verdict(List<Contour> p, PocketTechnology t, AdaptivePocket.Plan plan) {
        List<Contour> boundary = RegionOffsetter.oriented(p.get(0), p.subList(1, p.size()));
        ToolpathSection a = plan.toolpath().sections().get(0);
        double[] ratio = {0, 0};
        double s = t.cutFraction() * t.toolDiameterMm();
        double bound = AdaptivePocketTest.bound(t);
        Engagement e =
                Engagement.of(boundary, t.radiusMm(), a.start(), a.moves(), t.finishFeedMmPerMin(), (mi, q, deg) -> {
                    Move mv = a.moves().get(mi);
                    double f = mv instanceof Move.Linear l ? l.feedMmPerMin() : ((Move.Circular) mv).feedMmPerMin();
                    double rr =
                            f * Engagement.widthMm(Math.max(0, deg - 3), t.radiusMm()) / (t.feedMmPerMin() * 1.1 * s);
                    ratio[0] = Math.max(ratio[0], rr);
                    if (f == t.feedMmPerMin()) {
                        ratio[1] = Math.max(ratio[1], deg);
                    }
                });
        return String.format(
                Locale.ROOT,
                "ok fullFeedMax %.1f bound %.1f ratio %.3f slowed %d moves %.1f mm worst %.0f low %.2f walks %d",
                ratio[1],
                bound,
                ratio[0],
                plan.slowed().moves(),
                plan.slowed().lengthMm(),
                plan.slowed().worstDeg(),
                plan.slowed().lowestFactor(),
                plan.walks());
    }
}
