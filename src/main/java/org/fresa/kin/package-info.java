/**
 * Robot kinematics: Denavit-Hartenberg chains, forward kinematics, Jacobians, inverse kinematics
 * and the hybrid Tricept. Pure and immutable at its boundary; mm and degrees at the boundary
 * (names say which), radians inside. Dependencies: {@code geom} and Symja (symbolic FK) only.
 */
package org.fresa.kin;
