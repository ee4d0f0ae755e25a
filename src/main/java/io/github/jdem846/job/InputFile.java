package io.github.jdem846.job;

import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;

/**
 * A job's input as files for the length of the job: the DEM given, or the bundled sample DEM ({@link
 * DemReader#SAMPLE_RESOURCE}) copied to a temporary file that closing deletes.
 */
final class InputFile implements AutoCloseable {

    private final DemInput input;
    private final Path temporary;

    private InputFile(DemInput input, Path temporary) {
        this.input = input;
        this.temporary = temporary;
    }

    /** {@code input}, or the sample when it is null. */
    static InputFile open(DemInput input) throws IOException {
        if (input != null) {
            return new InputFile(input, null);
        }
        Path tmp = Files.createTempFile("jdem846-sample-", ".tif");
        try (InputStream in = DemReader.class.getResourceAsStream(DemReader.SAMPLE_RESOURCE)) {
            if (in == null) {
                throw new IOException("the bundled sample DEM is missing from the jar");
            }
            Files.copy(in, tmp, StandardCopyOption.REPLACE_EXISTING);
        } catch (IOException | RuntimeException e) {
            Files.deleteIfExists(tmp);
            throw e;
        }
        return new InputFile(DemInput.of(tmp), tmp);
    }

    /** @return the files to read */
    DemInput input() {
        return input;
    }

    @Override
    public void close() throws IOException {
        if (temporary != null) {
            Files.deleteIfExists(temporary);
        }
    }
}
