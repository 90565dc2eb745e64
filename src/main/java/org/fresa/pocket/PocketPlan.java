package org.fresa.pocket;

import java.util.List;

/**
 * The passes of a pocket: generated outside in along the recognition tree, milled inside out
 * (Table 7.3).
 *
 * @param recognition the tree and the reported sizes
 * @param technology the technology data
 * @param generated passes in generation order (finishing pass first)
 * @param milled passes in machining order (the reverse)
 */
public record PocketPlan(
        Recognition.Result recognition,
        PocketTechnology technology,
        List<PocketPass> generated,
        List<PocketPass> milled) {

    public PocketPlan {
        generated = List.copyOf(generated);
        milled = List.copyOf(milled);
    }
}
