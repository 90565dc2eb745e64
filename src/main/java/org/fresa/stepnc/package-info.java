/**
 * ISO 10303-21 (Part 21) reading and the ISO 14649 (STEP-NC) model bound from it. Readers never
 * plan paths. Dependencies: {@code model}, {@code geom}.
 */
package org.fresa.stepnc;
