package io.github.jdem846.bench;

import java.io.IOException;
import java.nio.file.Path;

final class AccuracyReport {
    private AccuracyReport() {
    }

    static void write(Path in, Path images, Path tables) throws IOException {
        throw new UnsupportedOperationException();
    }
}
