/**
 * Three-dimensional perspective views of a DEM: the shaded relief of {@link io.github.jdem846.job.ReliefJob} draped
 * on the terrain and seen through a pinhole {@link io.github.jdem846.view.Camera} ({@link
 * io.github.jdem846.view.ViewJob} from a file, {@link io.github.jdem846.view.PerspectiveRenderer} from a grid and a
 * picture in memory). docs/view.md describes the camera model.
 */
package io.github.jdem846.view;
