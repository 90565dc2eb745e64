/**
 * 2.5D toolpaths for STEP-NC workingsteps. Dependencies: {@code pocket}, {@code stepnc},
 * {@code model}, {@code geom}.
 */
package org.fresa.toolpath;
