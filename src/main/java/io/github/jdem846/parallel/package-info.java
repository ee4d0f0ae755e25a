/**
 * Running the parts of a computation on a {@link java.util.concurrent.ForkJoinPool} so that interrupting the calling
 * thread stops it promptly: {@link io.github.jdem846.parallel.Cancellation}.
 */
package io.github.jdem846.parallel;
