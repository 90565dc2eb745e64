package org.fresa.app.cli;

import static org.junit.jupiter.api.Assertions.assertEquals;

import org.fresa.model.Placement;
import org.junit.jupiter.api.Test;

class PlacementOptionsTest {

    @Test
    void placementOptionsReadAsTheThesisTable51() throws org.fresa.model.CamInputException {
        assertEquals(new Placement(450, 0, 350, 0, 0, 0), PlacementOptions.parseRobotTable("450,0,350"));
        assertEquals(new Placement(300, 300, 745, 0, 0, 30), PlacementOptions.parseRobotTable("300,300,745,30"));
        assertEquals(new Placement(0, 10, 0, -90, 0, 0), PlacementOptions.parseTablePiece("0,10,0,-90"));
        org.junit.jupiter.api.Assertions.assertThrows(
                org.fresa.model.CamInputException.class, () -> PlacementOptions.parseTablePiece("0,ten,0"));
        org.junit.jupiter.api.Assertions.assertThrows(
                org.fresa.model.CamInputException.class, () -> PlacementOptions.parseRobotTable("1,2"));
    }
}
