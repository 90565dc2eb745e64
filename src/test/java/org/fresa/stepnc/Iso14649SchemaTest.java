package org.fresa.stepnc;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.junit.jupiter.api.Test;
import org.junit.jupiter.params.ParameterizedTest;
import org.junit.jupiter.params.provider.CsvSource;

class Iso14649SchemaTest {

    /** Arities checked against the files (seed 002 section 5.1 and ISO 14649-11 example 1). */
    @ParameterizedTest
    @CsvSource(textBlock = """
            PROJECT, 6
            WORKPIECE, 7
            WORKPLAN, 5
            MACHINING_WORKINGSTEP, 5
            ROUND_HOLE, 8
            CLOSED_POCKET, 11
            PLANAR_FACE, 9
            SLOT, 8
            STEP, 8
            BOTTOM_AND_SIDE_ROUGH_MILLING, 16
            PLANE_FINISH_MILLING, 14
            DRILLING, 14
            CENTER_DRILLING, 14
            REAMING, 17
            MULTISTEP_DRILLING, 18
            TAPPING, 15
            FREEFORM_OPERATION, 12
            MILLING_TECHNOLOGY, 9
            MILLING_MACHINE_FUNCTIONS, 10
            MILLING_CUTTING_TOOL, 6
            FACEMILL, 5
            TAPERED_ENDMILL, 6
            MILLING_TOOL_DIMENSION, 7
            CUTTING_COMPONENT, 5
            DRILLING_TYPE_STRATEGY, 6
            CONTOUR_PARALLEL, 4
            BIDIRECTIONAL_MILLING, 5
            CONTOUR_BIDIRECTIONAL, 6
            RECTANGULAR_CLOSED_PROFILE, 3
            """)
    void attributeCountsMatchTheStandardWithInheritedAttributesFirst(String entity, int count) {
        assertEquals(
                count,
                Iso14649Schema.get()
                        .find(entity)
                        .orElseThrow()
                        .def()
                        .attributes()
                        .size());
    }

    @ParameterizedTest
    @CsvSource(textBlock = """
            BIDIRECTIONAL, BIDIRECTIONAL_MILLING
            UNIDIRECTIONAL, UNIDIRECTIONAL_MILLING
            EXPLICIT, EXPLICIT_STRATEGY
            TOOL_DIMENSION, MILLING_TOOL_DIMENSION
            ELEMENTARY_SURFACE, PLANE
            """)
    void draftSpellingsAreAliasesOfThePublishedNames(String draft, String published) {
        Iso14649Schema.Lookup l = Iso14649Schema.get().find(draft).orElseThrow();
        assertEquals(published, l.def().name());
        assertTrue(l.isAlias());
    }

    @Test
    void inheritedAttributesComeFirstInFileOrder() {
        var d = Iso14649Schema.get().find("DRILLING").orElseThrow().def();
        assertEquals(0, d.indexOf("its_toolpath"));
        assertEquals(2, d.indexOf("its_id"));
        assertEquals(9, d.indexOf("cutting_depth"));
        assertTrue(d.isA("MACHINING_OPERATION"));
    }

    @Test
    void abstractSupertypesAreNotAcceptedAsInstances() {
        assertTrue(Iso14649Schema.get().find("MACHINING_FEATURE").isEmpty());
        assertTrue(Iso14649Schema.get().find("NO_SUCH_ENTITY").isEmpty());
    }
}
