package org.fresa.ui;

import static org.junit.jupiter.api.Assertions.assertArrayEquals;
import static org.junit.jupiter.api.Assertions.assertEquals;
import static org.junit.jupiter.api.Assertions.assertThrows;
import static org.junit.jupiter.api.Assertions.assertTrue;

import org.fresa.job.Job;
import org.fresa.job.JobTask;
import org.fresa.kin.Robots;
import org.fresa.model.CamInputException;
import org.junit.jupiter.api.Test;

class RobotViewModelTest {

    @Test
    void theIrb140DhTableIsShownAsTheSpecPrintsIt() {
        RobotViewModel vm = new RobotViewModel();
        assertEquals(6, vm.dhRows().size());
        assertArrayEquals(new String[] {"q1", "R", "70", "352", "-90", "q1", "-180 deg", "180 deg"},
                vm.dhRows().get(0));
        assertEquals("q2 - 90", vm.dhRows().get(1)[5]);
        assertEquals("q5 + 180", vm.dhRows().get(4)[5]);
    }

    @Test
    void theAdeptOneShowsItsPrismaticJointAndTheTriceptItsParameters() throws CamInputException {
        RobotViewModel vm = new RobotViewModel();
        vm.choose("adept-one");
        assertEquals("P", vm.dhRows().get(2)[1]);
        assertEquals("195 mm", vm.dhRows().get(2)[7]);
        vm.choose("tricept806");
        assertEquals(6, vm.dhRows().size());
        assertTrue(String.join("\n", vm.parameters()).contains("r_p = 200 mm"), vm.parameters().toString());
        assertTrue(String.join("\n", vm.parameters()).contains("e_ffl = 250 mm"));
    }

    @Test
    void anUnknownRobotIsRefusedAndTheShownOneKept() {
        RobotViewModel vm = new RobotViewModel();
        assertThrows(CamInputException.class, () -> vm.choose("no-such-robot"));
        assertEquals("irb140", vm.robot().name());
    }

    @Test
    void theChoiceIsWrittenIntoTheJobsRobotSettings() throws CamInputException {
        RobotViewModel vm = new RobotViewModel();
        vm.choose("tricept806");
        Job j = vm.applyTo(Job.empty(JobTask.ROBOT));
        assertEquals("tricept806", j.robot().orElseThrow().robot());
        assertTrue(vm.fromJob(j).isEmpty());
    }

    @Test
    void theSymbolicForwardKinematicsIsWrittenInTheJointVariables() {
        String text = RobotViewModel.symbolic(Robots.adeptOne());
        assertTrue(text.contains("px = "), text);
        assertTrue(text.contains("q1"), text);
    }
}
