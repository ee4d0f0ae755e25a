/**
 * One picture of one DEM file, from file to pixels or to an image file: {@link io.github.jdem846.job.ReliefJob}
 * plans the read (window, halo, decimation), reads, lights ({@link io.github.jdem846.job.Sun}) and renders a
 * {@link io.github.jdem846.job.Product}; {@link io.github.jdem846.job.ReliefResult} holds and writes it. The
 * command line is this job with its options parsed.
 */
package io.github.jdem846.job;
