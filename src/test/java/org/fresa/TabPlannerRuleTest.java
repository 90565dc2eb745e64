package org.fresa;

import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertTrue;

import com.tngtech.archunit.core.domain.JavaClasses;
import com.tngtech.archunit.core.importer.ClassFileImporter;
import com.tngtech.archunit.lang.EvaluationResult;
import org.fresa.fixture.tab.TabThroughTheService;
import org.fresa.fixture.tab.TabWithAPlannerOfItsOwn;
import org.junit.jupiter.api.Test;

/** The rule "no tab runs a planner of its own" catches a tab that does, and passes one that does not. */
class TabPlannerRuleTest {

    @Test
    void aTabThatPlansItselfBreaksTheRule() {
        JavaClasses fixture = new ClassFileImporter().importClasses(TabWithAPlannerOfItsOwn.class);
        EvaluationResult r = ArchitectureTest.tabsComputeThroughTheModuleServices("org.fresa.fixture.tab..")
                .evaluate(fixture);
        assertTrue(r.hasViolation());
        assertTrue(
                r.getFailureReport().toString().contains("ToolpathPlanner.plan"),
                r.getFailureReport().toString());
    }

    @Test
    void aTabThatComputesThroughTheServiceKeepsIt() {
        JavaClasses fixture = new ClassFileImporter().importClasses(TabThroughTheService.class);
        EvaluationResult r = ArchitectureTest.tabsComputeThroughTheModuleServices("org.fresa.fixture.tab..")
                .evaluate(fixture);
        assertEquals(false, r.hasViolation(), r.getFailureReport().toString());
    }
}
