package org.fresa.app.cli;

import org.fresa.model.Placement;
import org.fresa.setting.SettingRanges;

/** The placements of the robot command's options, read from their comma-separated numbers. */
final class PlacementOptions {
    private PlacementOptions() {}

    /**
     * Reads {@code --robot-table X,Y,Z[,RZ]} (mm, deg).
     *
     * @throws org.fresa.model.CamInputException naming the option when the text is not 3 or 4 numbers
     */
    public static Placement parseRobotTable(String text) throws org.fresa.model.CamInputException {
        double[] v = SettingRanges.Robot.numbers("--robot-table", text, 3, 4);
        return new Placement(v[0], v[1], v[2], 0, 0, v.length > 3 ? v[3] : 0);
    }

    /**
     * Reads {@code --table-piece X,Y,Z[,RX,RY,RZ]} (mm, deg; R = Rz*Ry*Rx).
     *
     * @throws org.fresa.model.CamInputException naming the option when the text is not 3 to 6 numbers
     */
    public static Placement parseTablePiece(String text) throws org.fresa.model.CamInputException {
        double[] v = SettingRanges.Robot.numbers("--table-piece", text, 3, 6);
        return new Placement(
                v[0], v[1], v[2], v.length > 3 ? v[3] : 0, v.length > 4 ? v[4] : 0, v.length > 5 ? v[5] : 0);
    }
}
