package io.github.jdem846.io;

import java.nio.file.Path;
import java.util.List;
import java.util.Objects;

/**
 * What a render reads as one grid: one DEM file, or several files read together as a mosaic (one CRS, one cell
 * size, one grid; gaps are no-data, overlapping cells the mean of the files' valid values; see
 * {@link DemReader}).
 *
 * @param files the DEM files, at least one; a {@code .hdr} stands for its data file
 */
public record DemInput(List<Path> files) {

    /**
     * Copies the list of files and checks that it holds at least one.
     *
     * @param files the DEM files, at least one; a {@code .hdr} stands for its data file
     */
    public DemInput {
        files = List.copyOf(Objects.requireNonNull(files, "files"));
        if (files.isEmpty()) {
            throw new IllegalArgumentException("a DEM input needs at least one file");
        }
    }

    /**
     * One DEM file.
     *
     * @param file the file
     * @return the input
     */
    public static DemInput of(Path file) {
        return new DemInput(List.of(Objects.requireNonNull(file, "file")));
    }

    /**
     * Several DEM files read as one grid (one file is read as itself).
     *
     * @param files the files
     * @return the input
     */
    public static DemInput of(List<Path> files) {
        return new DemInput(files);
    }

    /** {@return true when this is one file} */
    public boolean isSingleFile() {
        return files.size() == 1;
    }

    /** {@return the first file (the only one of a single-file input)} */
    public Path first() {
        return files.get(0);
    }

    /** @return the file, or a short description of the files, for messages */
    @Override
    public String toString() {
        return isSingleFile() ? first().toString()
                : files.size() + " files (" + first() + (files.size() > 1 ? ", …)" : ")");
    }
}
