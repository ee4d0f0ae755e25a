package io.github.jdem846.output;

import java.io.IOException;
import java.nio.file.Files;
import java.nio.file.Path;
import java.util.Collection;
import java.util.List;
import java.util.Objects;

/**
 * Refuses an output that would replace or delete an input: the image or one of its sidecars is the same file as
 * the DEM or one of the files read with it ({@code .hdr}, {@code .prj}), however it is spelt ({@code x/../dem.tif},
 * a symbolic link, a hard link: the same file key). Done before any work, so that nothing is read or written in
 * vain.
 */
public final class InputProtection {

    private InputProtection() {
    }

    /**
     * Checks that writing {@code image} with {@code options} ({@link ImageOutput#filesWritten}) touches none of
     * {@code inputFiles} (e.g. {@link io.github.jdem846.io.DemReader#filesOf}).
     *
     * @throws OutputOverwritesInputException naming the output file and the input it would destroy
     * @throws IOException                    when the file system cannot tell whether two files are the same
     */
    public static void check(Path image, WriteOptions options, Collection<Path> inputFiles) throws IOException {
        List<Path> outputs = ImageOutput.filesWritten(image, options);
        for (Path out : outputs) {
            if (!Files.exists(out)) {
                continue;   // a file that does not exist yet cannot be an input
            }
            for (Path in : Objects.requireNonNull(inputFiles, "inputFiles")) {
                if (Files.exists(in) && Files.isSameFile(out, in)) {
                    throw new OutputOverwritesInputException(out, in, out.equals(image) ? null : image);
                }
            }
        }
    }
}
