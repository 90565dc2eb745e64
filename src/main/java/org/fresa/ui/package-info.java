/**
 * The desktop application (Swing): the main window, one tab per module, the shared plot view
 * and the task runner. The only package that uses {@code javax.swing}. Each panel keeps its
 * state and validation in a Swing-free {@code *ViewModel}, tested without a screen; long work
 * runs in a {@link javax.swing.SwingWorker} calling the {@code job} services.
 */
package org.fresa.ui;
