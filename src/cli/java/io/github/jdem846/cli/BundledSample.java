package io.github.jdem846.cli;

import io.github.jdem846.io.DemInfo;
import io.github.jdem846.io.DemInput;
import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.LoadedDem;
import io.github.jdem846.io.ReadRequest;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;

/**
 * The DEM drawn when no FILE is given: a 600 × 400 crop of SRTM 30 m of Big Tujunga, California, carried in
 * {@code jdem846-cli.jar} only (the library jar has no data). It is copied to a file of its own name in a new
 * temporary directory, which the JVM deletes when it exits.
 */
final class BundledSample {

    /** The file's name, also its resource name in this package's {@code sample} folder. */
    static final String NAME = "bigtujunga_crop600x400_v04_int16_deflate_pred2_tile256.tif";

    private static final String RESOURCE = "/io/github/jdem846/sample/" + NAME;

    private BundledSample() {
    }

    /**
     * Copies the sample out of the jar.
     *
     * @return the copy, deleted (with its directory) when the JVM exits
     * @throws IOException when the jar lacks it or it cannot be written
     */
    static DemInput extract() throws IOException {
        Path dir = Files.createTempDirectory("jdem846-sample-");
        dir.toFile().deleteOnExit();
        Path file = dir.resolve(NAME);
        file.toFile().deleteOnExit();
        try (InputStream in = BundledSample.class.getResourceAsStream(RESOURCE)) {
            if (in == null) {
                throw new IOException("the bundled sample " + RESOURCE + " is missing from the jar");
            }
            Files.copy(in, file);
        }
        return DemInput.of(file);
    }

    /**
     * Reads the whole sample with its header, named "bundled sample …" rather than by its temporary copy.
     *
     * @return the grid and its header
     * @throws IOException when it cannot be copied out of the jar
     */
    static LoadedDem load() throws IOException {
        DemInput input = extract();
        LoadedDem loaded = DemReader.load(input.first(), ReadRequest.FULL);
        DemInfo i = loaded.info();
        return new LoadedDem(new DemInfo("bundled sample " + NAME, i.format(), i.dataType(), i.bands(), i.geometry(),
                i.declaredNoData(), i.notices()), loaded.dem(), loaded.sourceStatistics());
    }
}
