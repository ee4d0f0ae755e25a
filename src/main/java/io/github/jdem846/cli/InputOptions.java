package io.github.jdem846.cli;

import io.github.jdem846.io.DemReader;
import io.github.jdem846.io.Window;
import io.github.jdem846.render.DemLoader;
import io.github.jdem846.render.OutputSize;
import java.io.IOException;
import java.io.InputStream;
import java.nio.file.Files;
import java.nio.file.Path;
import java.nio.file.StandardCopyOption;
import java.util.Locale;
import picocli.CommandLine.Mixin;
import picocli.CommandLine.Option;
import picocli.CommandLine.Parameters;

/**
 * The DEM to draw and which part of it at what size: {@code [FILE] --window --width --height --scale}. Without FILE
 * the bundled sample DEM is used.
 */
public final class InputOptions {

    @Parameters(index = "0", arity = "0..1", paramLabel = "FILE",
            description = "GeoTIFF, GridFloat (.flt), ESRI ASCII (.asc), BIL (.bil) or SRTM .hgt; the bundled "
                    + "sample DEM (Big Tujunga, California) when omitted.")
    Path file;

    @Mixin
    BodyOptions bodyOptions;

    @Option(names = "--window", paramLabel = "W,S,E,N|cells:COL,ROW,W,H",
            description = "Render only this part: a box in the DEM's CRS units (west,south,east,north) or a cell "
                    + "rectangle 'cells:col,row,width,height' (row 0 = north). Only the window and the halo the "
                    + "stages need are read.")
    String window;

    @Option(names = "--width", paramLabel = "PIXELS", description = "Output width (height follows the aspect "
            + "ratio unless --height is given too).")
    Integer width;

    @Option(names = "--height", paramLabel = "PIXELS", description = "Output height.")
    Integer height;

    @Option(names = "--scale", paramLabel = "FACTOR",
            description = "Output pixels per DEM cell, e.g. 0.25 for a quarter-size picture.")
    Double scale;

    /** The output size these options ask for. */
    OutputSize size() {
        if (scale != null) {
            if (width != null || height != null) {
                throw new IllegalArgumentException("give either --scale or --width/--height, not both");
            }
            return OutputSize.scale(scale);
        }
        if (width != null && height != null) {
            return new OutputSize(positive(width, "--width"), positive(height, "--height"), 0);
        }
        if (width != null) {
            return OutputSize.width(positive(width, "--width"));
        }
        if (height != null) {
            return OutputSize.height(positive(height, "--height"));
        }
        return OutputSize.FULL;
    }

    /** True when {@code --window} was given. */
    boolean hasWindow() {
        return window != null;
    }

    /** The window, or {@code null} for the whole grid. */
    Window window() {
        if (window == null) {
            return null;
        }
        String text = window.trim();
        boolean cells = text.toLowerCase(Locale.ROOT).startsWith("cells:");
        String[] parts = (cells ? text.substring(6) : text).split(",");
        String expected = "expected --window WEST,SOUTH,EAST,NORTH in the DEM's CRS units or "
                + "cells:COL,ROW,WIDTH,HEIGHT";
        if (parts.length != 4) {
            throw new IllegalArgumentException("'" + window + "' is not a window: " + expected);
        }
        try {
            if (cells) {
                return Window.cells(Integer.parseInt(parts[0].trim()), Integer.parseInt(parts[1].trim()),
                        Integer.parseInt(parts[2].trim()), Integer.parseInt(parts[3].trim()));
            }
            return Window.world(Double.parseDouble(parts[0].trim()), Double.parseDouble(parts[1].trim()),
                    Double.parseDouble(parts[2].trim()), Double.parseDouble(parts[3].trim()));
        } catch (NumberFormatException e) {
            throw new IllegalArgumentException("'" + window + "' is not a window: " + expected);
        }
    }

    /**
     * Loads what the picture needs, with {@code halo} (and the whole file's elevation range when asked); the
     * bundled sample when no FILE was given.
     */
    DemLoader.Loaded load(DemLoader.Halo halo, boolean fileStatistics) throws IOException {
        if (file != null) {
            return DemLoader.load(file, window(), size(), halo, fileStatistics, body().ellipsoid());
        }
        Path tmp = Files.createTempFile("jdem846-sample-", ".tif");
        try {
            try (InputStream in = DemReader.class.getResourceAsStream(DemReader.SAMPLE_RESOURCE)) {
                if (in == null) {
                    throw new IOException("the bundled sample DEM is missing from the jar");
                }
                Files.copy(in, tmp, StandardCopyOption.REPLACE_EXISTING);
            }
            return DemLoader.load(tmp, window(), size(), halo, fileStatistics, body().ellipsoid());
        } finally {
            Files.deleteIfExists(tmp);
        }
    }

    /** The body of {@code --body}/{@code --radius}; the Earth by default. */
    io.github.jdem846.sun.Body body() {
        return bodyOptions.body();
    }

    /** The DEM file named, or {@code null} for the sample. */
    Path file() {
        return file;
    }

    private static int positive(int v, String option) {
        if (v < 1) {
            throw new IllegalArgumentException(option + " must be at least 1 pixel, got " + v);
        }
        return v;
    }
}
