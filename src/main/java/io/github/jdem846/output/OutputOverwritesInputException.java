package io.github.jdem846.output;

import java.io.IOException;
import java.nio.file.Path;

/**
 * An output file that is one of the input's files or their sidecars: writing it would destroy the input. Thrown by
 * {@link InputProtection} before any work; the CLI reports it as bad usage (exit status 2).
 */
public final class OutputOverwritesInputException extends IOException {

    private static final long serialVersionUID = 1L;

    private final transient Path output;
    private final transient Path input;

    /**
     * @param output    the file that would be written
     * @param input     the input file it is
     * @param image     the image whose sidecar {@code output} is, or {@code null} when {@code output} is the image
     * @param sidecarOf the input data file whose sidecar {@code input} is, or {@code null} when {@code input} is
     *                  read itself
     */
    OutputOverwritesInputException(Path output, Path input, Path image, Path sidecarOf) {
        super(message(output, input, image, sidecarOf));
        this.output = output;
        this.input = input;
    }

    private static String message(Path output, Path input, Path image, Path sidecarOf) {
        String what = image == null ? "cannot write " + output
                : "cannot write " + output + " (a sidecar of " + image + ")";
        String same = output.equals(input) ? "" : " (the same file)";
        String which = sidecarOf != null ? "it is " + input + same + ", a sidecar of the input file " + sidecarOf
                : output.equals(input) ? "it is the input file itself"
                : "it is the input file " + input + same;
        return what + ": " + which + ", which would be lost; choose another output name";
    }

    /** {@return the output file that was refused} */
    public Path output() {
        return output;
    }

    /** {@return the input file it would have replaced} */
    public Path input() {
        return input;
    }
}
