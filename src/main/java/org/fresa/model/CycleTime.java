package org.fresa.model;

import java.util.List;
import org.fresa.geom.Vec3;

/**
 * A cycle-time estimate without acceleration: each feed move takes its length over its feed,
 * each rapid its length over the stated rapid rate, each dwell its time. Arc lengths are exact
 * (helices count their rise). Spindle stops and starts count as instantaneous: the time a
 * spindle takes to run down and up depends on the machine, which this estimate does not know.
 *
 * @param feedLengthMm total length of the feed moves
 * @param rapidLengthMm total length of the rapids
 * @param feedSeconds time spent at feed
 * @param rapidSeconds time spent in rapids
 * @param dwellSeconds time spent in dwells
 */
public record CycleTime(
        double feedLengthMm, double rapidLengthMm, double feedSeconds, double rapidSeconds, double dwellSeconds) {

    public static final CycleTime ZERO = new CycleTime(0, 0, 0, 0, 0);

    /** Without dwells. */
    public CycleTime(double feedLengthMm, double rapidLengthMm, double feedSeconds, double rapidSeconds) {
        this(feedLengthMm, rapidLengthMm, feedSeconds, rapidSeconds, 0);
    }

    /** Total time in seconds. */
    public double seconds() {
        return feedSeconds + rapidSeconds + dwellSeconds;
    }

    public CycleTime plus(CycleTime o) {
        return new CycleTime(
                feedLengthMm + o.feedLengthMm,
                rapidLengthMm + o.rapidLengthMm,
                feedSeconds + o.feedSeconds,
                rapidSeconds + o.rapidSeconds,
                dwellSeconds + o.dwellSeconds);
    }

    /** The path length of one move starting at {@code from} (mm); 0 for dwells and spindle events. */
    public static double lengthMm(Vec3 from, Move m) {
        if (!m.travels()) {
            return 0;
        }
        if (m instanceof Move.Circular c) {
            return ArcGeometry.of(from, c).lengthMm();
        }
        return from.distance(m.end());
    }

    /** The time of one move starting at {@code from} (s). */
    public static double seconds(Vec3 from, Move m, double rapidMmPerMin) {
        if (m instanceof Move.Dwell d) {
            return d.seconds();
        }
        if (!m.travels()) {
            return 0;
        }
        return lengthMm(from, m) / rate(m, rapidMmPerMin) * 60;
    }

    /** The rate the move runs at (mm/min): its feed, or the rapid rate (also for moves that do not travel). */
    public static double rate(Move m, double rapidMmPerMin) {
        if (m instanceof Move.Linear l) {
            return l.feedMmPerMin();
        }
        if (m instanceof Move.Circular c) {
            return c.feedMmPerMin();
        }
        return rapidMmPerMin;
    }

    /** The moves of a section from its start point. */
    public static CycleTime of(ToolpathSection s, double rapidMmPerMin) {
        return of(s.start(), s.moves(), rapidMmPerMin);
    }

    /** Moves run one after the other from {@code start}. */
    public static CycleTime of(Vec3 start, List<Move> moves, double rapidMmPerMin) {
        if (!(rapidMmPerMin > 0)) {
            throw new IllegalArgumentException("rapid rate must be > 0: " + rapidMmPerMin);
        }
        double fl = 0;
        double rl = 0;
        double fs = 0;
        double rs = 0;
        double ds = 0;
        Vec3 at = start;
        for (Move m : moves) {
            double len = lengthMm(at, m);
            if (m instanceof Move.Rapid) {
                rl += len;
                rs += len / rapidMmPerMin * 60;
            } else if (m instanceof Move.Linear || m instanceof Move.Circular) {
                fl += len;
                fs += len / rate(m, rapidMmPerMin) * 60;
            } else if (m instanceof Move.Dwell d) {
                ds += d.seconds();
            }
            at = m.end();
        }
        return new CycleTime(fl, rl, fs, rs, ds);
    }
}
