package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertAll;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import java.io.StringReader;
import java.nio.file.Path;
import java.util.Set;
import org.junit.jupiter.api.Test;

/** What stays of a file once bound: the instances asked for, each as it was read. */
class StepFileOnlyTest {

    private static final String FILE = "ISO-10303-21;\nHEADER;\nFILE_SCHEMA(('X'));\nENDSEC;\nDATA;\n"
            + "#1=A('a''b',$,*,-0.0,1.5E300,-7,.T.,\"0F\",(#2,(#3,TYPE(#1))),());\n"
            + "#2=(B(1)C('c',#1));\n"
            + "#3=D(#2);\n"
            + "ENDSEC;\nEND-ISO-10303-21;\n";

    @Test
    void theInstancesKeptDecodeAsTheyWereReadAndTheOthersAreGone() throws Exception {
        StepFile f = Part21Reader.read(new StringReader(FILE), "t.stp");
        StepFile kept = f.only(Set.of(1L, 2L));
        assertAll(
                () -> assertEquals(2, kept.size()),
                () -> assertEquals(f.instance(1).orElseThrow(), kept.instance(1).orElseThrow()),
                () -> assertEquals(f.instance(2).orElseThrow(), kept.instance(2).orElseThrow()),
                () -> assertTrue(kept.instance(3).isEmpty()),
                () -> assertEquals(f.header(), kept.header()),
                () -> assertEquals(f.source(), kept.source()));
    }

    @Test
    void aProgramForPlanningFindsEveryFeaturesWorkpieceAsTheWholeFileDoes() throws Exception {
        StepNcProgram p = StepNcReader.read(Path.of("samples/stepnc/iso14649-11-example1.stp"));
        StepNcProgram lean = p.forPlanning();
        assertTrue(
                lean.file().size() < p.file().size(),
                lean.file().size() + " of " + p.file().size());
        for (MachiningWorkingstep w : p.workingsteps()) {
            assertEquals(p.workpieceOf(w.feature()), lean.workpieceOf(w.feature()), w.id());
        }
        assertEquals(p.workingsteps(), lean.workingsteps());
        assertEquals(p.instanceCount(), lean.instanceCount());
    }
}
