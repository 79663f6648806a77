// casteljau's C++ library compiled to WebAssembly (wasm/: embind bindings,
// one file with the module embedded), wrapped so that bad input throws an
// Error carrying the library's own message: every binding returns
// {error: message} instead of throwing through WebAssembly.
'use strict';

(function () {
  /// Resolves to the library: the module's functions, each throwing on an error value.
  async function loadLibrary() {
    const module = await createCasteljau();  // eslint-disable-line no-undef
    const library = { module };
    for (const name of Object.keys(module)) {
      const f = module[name];
      if (typeof f !== 'function' || !/^[a-z]/.test(name) || name.startsWith('dynCall')) continue;
      library[name] = (...args) => {
        const result = f(...args);
        if (result && typeof result === 'object' && !ArrayBuffer.isView(result) && typeof result.error === 'string') {
          throw new Error(result.error);
        }
        return result;
      };
    }
    return library;
  }

  window.loadLibrary = loadLibrary;
})();
