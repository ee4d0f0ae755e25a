/**
 * The {@code jdem846} command line (picocli): each command parses its options into one {@code job.ReliefJob} or
 * library call. Not exported: the command line runs from {@code jdem846-cli.jar} on the class path.
 */
package io.github.jdem846.cli;
