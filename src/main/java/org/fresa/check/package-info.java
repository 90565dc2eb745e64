/**
 * The program check: every NC and robot program Fresa writes is read back before it is renamed
 * into place, and refused at its first unsafe block (a cutting move with the spindle stopped, a
 * word out of the machine's range, an entry steeper than the tool allows, a move below the floor).
 * Pure: text and models in, a verdict out, no file I/O. Dependencies: {@code post} (the robot
 * program model and the NC dialects), {@code geom}.
 */
package org.fresa.check;
